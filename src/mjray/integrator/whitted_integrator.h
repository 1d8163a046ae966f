#pragma once
/// Recursive ray tracing with the CS 488 Phong model, hard shadows and secondary rays.

#include <cstdint>

#include "mjray/accel/accelerator.h"
#include "mjray/core/color.h"
#include "mjray/core/rng.h"
#include "mjray/core/ray.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Limits on recursion (-r, -f).
struct IntegratorSettings {
  int max_reflection_depth = 8;  ///< reflection, glossy and Fresnel reflection rays
  int max_refraction_depth = 8;  ///< transmission rays
  int area_light_samples = 1;    ///< -s: N×N jittered shadow rays per area light
};

/// Rays cast, by kind; each thread keeps its own and they are summed at the end.
/// Cache-line aligned: each worker thread updates its own on every ray, so neighbours in an
/// array must not share a line (false sharing would serialise the threads).
struct alignas(64) RayCounters {
  uint64_t primary = 0;
  uint64_t secondary = 0;
  uint64_t shadow = 0;

  RayCounters& operator+=(const RayCounters& o) {
    primary += o.primary;
    secondary += o.secondary;
    shadow += o.shadow;
    return *this;
  }
  uint64_t total() const { return primary + secondary + shadow; }
};

/// Computes the colour seen along a camera ray.
class WhittedIntegrator {
 public:
  WhittedIntegrator(const World& world, const Accelerator& accel, IntegratorSettings settings)
      : world_(world), accel_(accel), settings_(settings) {}

  /// The colour along a primary ray (direction unit length); `random` supplies every sample.
  Color radiance(const Ray& ray, RandomStream& random, RayCounters& counters) const;

 private:
  /// Where a ray is in the recursion: bounces of each kind so far, and the weight its
  /// colour will have in the pixel (the product of the Kr/Kt factors along the way).
  struct Depth {
    int reflection = 0;
    int refraction = 0;
    float weight = 1;

    Depth reflected(float factor) const { return {reflection + 1, refraction, weight * factor}; }
    Depth refracted(float factor) const { return {reflection, refraction + 1, weight * factor}; }
  };

  Color trace(const Ray& ray, Depth depth, RandomStream& random, RayCounters& counters) const;
  /// ambient⊙kd + Σ lights (kd·max(0,n·l) + ks·max(0,r·v)^shininess)·I·att, with shadows.
  Color direct_light(const SurfaceInteraction& si, const Normal3& n, const Vector3& wo,
                     const Material& material, RandomStream& random, RayCounters& counters) const;
  /// The Phong reflection of one light sample at `light_point`, or black when it is behind
  /// the surface or in shadow.
  Color light_sample(const SurfaceInteraction& si, const Normal3& n, const Vector3& wo,
                     const PhongMaterial& phong, const Point3& light_point, const Color& intensity,
                     RayCounters& counters) const;
  /// Light arriving by reflection and refraction: the hook that the materials of the
  /// original project's extensions plug into. Plain Phong materials add nothing.
  Color secondary_light(const SurfaceInteraction& si, const Normal3& n, const Vector3& wo,
                        const Material& material, Depth depth, RandomStream& random,
                        RayCounters& counters) const;
  /// Kr · reflected + Kt · refracted for a dielectric boundary; kr_of_cosine gives Kr from the
  /// cosine of the incident angle and the two indices (constant, or Fresnel).
  template <class ReflectanceFunction>
  Color dielectric_light(const SurfaceInteraction& si, const Normal3& n, const Vector3& wo,
                         float eta_outside, float eta_inside, ReflectanceFunction kr_of_cosine,
                         Depth depth, RandomStream& random, RayCounters& counters) const;
  /// The light arriving along a secondary ray leaving si.
  Color trace_secondary(const SurfaceInteraction& si, const Vector3& direction, Depth depth,
                        RandomStream& random, RayCounters& counters) const;

  const World& world_;
  const Accelerator& accel_;
  IntegratorSettings settings_;
};

}  // namespace mjray
