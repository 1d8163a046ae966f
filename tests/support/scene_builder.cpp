#include "support/scene_builder.h"

#include <cmath>
#include <numbers>

#include "mjray/scene/flatten.h"

namespace mjray::test {

World flattened_world(std::vector<std::shared_ptr<const SceneNode>> nodes, std::vector<Light> lights) {
  RenderJob job;
  job.root = group(std::move(nodes));
  job.lights = std::move(lights);
  return flatten(job, nullptr);
}

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

TriangleMesh lathe(const std::vector<Point2>& outline, int segments) {
  TriangleMesh m;
  const float pi = std::numbers::pi_v<float>;
  const size_t n = outline.size();
  for (size_t i = 0; i < n; ++i) {
    const Point2 a = outline[i], b = outline[(i + 1) % n];
    // The band's outward normal in the (r, y) plane, and a ring of vertices at each end.
    const float dr = b.u - a.u, dy = b.v - a.v, length = std::hypot(dr, dy);
    const float nr = dy / length, ny = -dr / length;
    const int first = int(m.positions.size());
    for (int s = 0; s <= segments; ++s) {
      const float angle = 2 * pi * float(s) / float(segments), c = std::cos(angle), sn = -std::sin(angle);
      m.positions.push_back({a.u * c, a.v, a.u * sn});
      m.positions.push_back({b.u * c, b.v, b.u * sn});
      m.normals.push_back({nr * c, ny, nr * sn});
    }
    const auto corner = [&](int s, int end) { return MeshCorner{first + 2 * s + end, -1, first / 2 + s}; };
    for (int s = 0; s < segments; ++s) {
      if (a.u > 0) m.triangles.push_back({corner(s, 0), corner(s + 1, 0), corner(s, 1)});
      if (b.u > 0) m.triangles.push_back({corner(s + 1, 0), corner(s + 1, 1), corner(s, 1)});
    }
  }
  m.polygon_count = m.triangles.size();
  return m;
}

}  // namespace mjray::test
