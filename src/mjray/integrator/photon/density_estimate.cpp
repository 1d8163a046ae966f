#include "mjray/integrator/photon/density_estimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace mjray {

Color irradiance_estimate(const KdTree<Photon>& map, const Point3& p, const Normal3& n, const DensityQuery& query) {
  constexpr float kCone = 1.1f;
  std::array<Neighbour, kMaxNeighbours> scratch;
  const size_t k = size_t(std::clamp(query.neighbours, 1, kMaxNeighbours));
  const auto near = map.nearest(p, query.max_radius * query.max_radius,
                                [&](const PackedNormal& normal) { return faces_alike(normal, n); },
                                std::span(scratch).first(k));
  if (near.found.empty() || !(near.radius2 > 0)) return {};
  const float radius = std::sqrt(near.radius2);
  Color sum;
  for (const Neighbour& found : near.found) {
    const float weight = 1 - std::sqrt(found.distance2) / (kCone * radius);
    sum += map.items()[found.index].power * weight;
  }
  // ∫ over the disc of the cone's weight is (1 − 2 / 3κ) π r².
  const float normalisation = (1 - 2 / (3 * kCone)) * std::numbers::pi_v<float> * near.radius2;
  return sum / normalisation;
}

}  // namespace mjray
