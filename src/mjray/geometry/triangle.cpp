#include "mjray/geometry/triangle.h"

namespace mjray {

std::optional<TriangleHit> intersect_triangle(const Ray& ray, Interval t_range, const Point3& p0,
                                              const Point3& p1, const Point3& p2) {
  using Floats = std::array<float, 3>;
  return intersect_triangle(WatertightRay(ray), t_range, std::bit_cast<Floats>(p0),
                            std::bit_cast<Floats>(p1), std::bit_cast<Floats>(p2));
}

}  // namespace mjray
