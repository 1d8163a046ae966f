// mesh:set_smooth_normals as a user sees it: a low-poly sphere, smoothed, shades like the
// true sphere; left as it is, it shows its facets.

#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "support/lua_script_test.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// A UV sphere of radius 1 as OBJ text: `rings` × `segments` facets, shared vertices, no vn.
std::string uv_sphere_obj(int rings, int segments) {
  std::ostringstream obj;
  obj << "v 0 1 0\n";
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = r * std::numbers::pi / rings, phi = s * 2 * std::numbers::pi / segments;
      obj << "v " << std::sin(theta) * std::cos(phi) << " " << std::cos(theta) << " " << -std::sin(theta) * std::sin(phi)
          << "\n";
    }
  obj << "v 0 -1 0\n";
  const auto v = [&](int r, int s) { return r == 0 ? 1 : r == rings ? 2 + (rings - 1) * segments : 2 + (r - 1) * segments + s % segments; };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      if (r == 0) obj << "f " << v(0, 0) << " " << v(1, s) << " " << v(1, s + 1) << "\n";
      else if (r == rings - 1) obj << "f " << v(r, s) << " " << v(rings, 0) << " " << v(r, s + 1) << "\n";
      else obj << "f " << v(r, s) << " " << v(r + 1, s) << " " << v(r + 1, s + 1) << " " << v(r, s + 1) << "\n";
    }
  return obj.str();
}

class MeshShading : public test::LuaScriptTest {
 protected:
  /// The 64×64 image of one unit "ball" node (its Lua expression, then `extra` calls on it).
  Image render_ball(const std::string& ball, const std::string& extra = "") {
    const std::string script = "root = gr.node('root')\nball = " + ball + "\n" + extra +
                               "ball:set_material(gr.material({0.7, 0.3, 0.2}, {0.5, 0.5, 0.5}, 25))\n"
                               "root:add_child(ball)\n"
                               "gr.render(root, 'out.png', 64, 64, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 30, {0.1, 0.1, 0.1},\n"
                               "          {gr.light({3, 4, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
    test::TestJob job(load(script), 0, test::oracle_options());
    return job.render();
  }
};

/// The mean absolute difference of two images over the disc of radius 17 px about the centre
/// (inside the silhouettes of both balls, which differ at the edge).
float mean_difference_inside(const Image& a, const Image& b) {
  double sum = 0;
  int count = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if ((x - 31.5) * (x - 31.5) + (y - 31.5) * (y - 31.5) > 17 * 17) continue;
      const Color d = a.at(x, y) - b.at(x, y);
      sum += (std::abs(d.r) + std::abs(d.g) + std::abs(d.b)) / 3;
      ++count;
    }
  return float(sum / count);
}

TEST_F(MeshShading, ASmoothedLowPolySphereShadesLikeTheTrueSphereAndAFlatOneShowsItsFacets) {
  write("ball.obj", uv_sphere_obj(12, 24));
  const Image truth = render_ball("gr.sphere('ball')");
  const Image flat = render_ball("gr.mesh('ball', 'ball.obj')");
  const Image smooth = render_ball("gr.mesh('ball', 'ball.obj')", "ball:set_smooth_normals(60)\n");
  const float flat_error = mean_difference_inside(flat, truth), smooth_error = mean_difference_inside(smooth, truth);
  // Measured: flat 0.029, smooth 0.0011 (of 1): interpolated normals leave only the error of
  // the facets' positions.
  EXPECT_LT(smooth_error, 0.003f) << smooth_error;
  EXPECT_GT(flat_error, 10 * smooth_error) << flat_error;
  // Facets meet at 15°, so under a 10° limit every edge is a crease: it shades as flat (to
  // float rounding: its normals are interpolated, the flat one's is the triangle's own).
  const Image creased = render_ball("gr.mesh('ball', 'ball.obj')", "ball:set_smooth_normals(10)\n");
  EXPECT_LT(mean_difference_inside(creased, flat), 1e-5f) << "flat " << flat_error << ", smooth " << smooth_error;
}

}  // namespace
}  // namespace mjray
