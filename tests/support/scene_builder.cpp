#include "support/scene_builder.h"

#include <cmath>
#include <numbers>

namespace mjray::test {

TriangleMesh uv_sphere(int rings, int segments) {
  TriangleMesh m;
  const float pi = std::numbers::pi_v<float>;
  m.positions.push_back({0, 1, 0});
  for (int r = 1; r < rings; ++r) {
    const float theta = pi * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2 * pi * float(s) / float(segments);
      m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  m.positions.push_back({0, -1, 0});
  const int bottom = int(m.positions.size()) - 1;
  auto ring = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  auto tri = [&](int a, int b, int c) { m.triangles.push_back({MeshCorner{a}, MeshCorner{b}, MeshCorner{c}}); };
  for (int s = 0; s < segments; ++s) tri(0, ring(1, s + 1), ring(1, s));
  for (int r = 1; r < rings - 1; ++r)
    for (int s = 0; s < segments; ++s) {
      tri(ring(r, s), ring(r, s + 1), ring(r + 1, s + 1));
      tri(ring(r, s), ring(r + 1, s + 1), ring(r + 1, s));
    }
  for (int s = 0; s < segments; ++s) tri(bottom, ring(rings - 1, s), ring(rings - 1, s + 1));
  m.polygon_count = m.triangles.size();
  return m;
}

}  // namespace mjray::test
