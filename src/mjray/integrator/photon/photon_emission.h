#pragma once
/// Where photons start: which light, which point on it, which direction, and the flux each
/// photon carries for its share of the light.

#include <cstdint>
#include <vector>

#include "mjray/core/color.h"
#include "mjray/core/ray.h"
#include "mjray/core/rng.h"
#include "mjray/geometry/shape.h"
#include "mjray/light/light.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Balls around the objects whose materials have specular lobes (one per mesh instance and
/// per shape), which caustic photons are aimed at; one ball around all of them when there
/// are more than a few dozen (each photon tests every ball).
std::vector<BoundingSphere> specular_targets(const World& world);

/// A photon leaving a light: its ray (unit direction) and flux, and which light it left.
struct EmittedPhoton {
  Ray ray;
  Color flux;
  uint32_t light = 0;
};

/// Spreads `count` photons over the lights in proportion to their power (stratified by photon
/// index), each from a point drawn on its light, in every direction or only toward target
/// balls. Where the cones toward several balls overlap, a photon's flux is divided by the
/// density of all of them, so that no direction counts twice.
class PhotonSource {
 public:
  /// Photons in every direction (the global photon map).
  explicit PhotonSource(const std::vector<Light>& lights);
  /// Photons toward `targets` only (the caustic map); none when there are no targets.
  PhotonSource(const std::vector<Light>& lights, std::vector<BoundingSphere> targets);

  /// Whether there is anything to emit (a light with power, and a target when aimed).
  bool empty() const { return choices_.empty(); }
  /// Photon `index` of `count`, drawing its numbers from `random`.
  EmittedPhoton emit(uint64_t index, uint64_t count, RandomStream& random) const;

 private:
  /// One light, and one target of it (or none: every direction), with its chance.
  struct Choice {
    uint32_t light;
    int target;
    double probability;
  };

  /// emit() for choice c, of a sun.
  EmittedPhoton emit_from_sun(const SunLight& sun, size_t c, uint64_t count, RandomStream& random) const;
  /// Drops choices without flux and scales the rest to probabilities.
  void normalise_choices();

  const std::vector<Light>& lights_;
  std::vector<BoundingSphere> targets_;
  std::vector<Choice> choices_;
  std::vector<double> cumulative_;  ///< of the choices' probabilities
};

}  // namespace mjray
