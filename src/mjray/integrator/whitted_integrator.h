#pragma once
/// Recursive ray tracing with the CS 488 Phong model, shadows and specular secondary rays.

#include "mjray/accel/accelerator.h"
#include "mjray/integrator/indirect_light.h"
#include "mjray/integrator/integrator.h"
#include "mjray/integrator/light_visibility.h"
#include "mjray/material/shading.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Limits on recursion (-r, -f) and light sampling (-s).
struct IntegratorSettings {
  int max_reflection_depth = 8;  ///< reflection, glossy and Fresnel reflection rays
  int max_refraction_depth = 8;  ///< transmission rays
  int area_light_samples = 1;    ///< -s: N×N jittered shadow rays per area light
  /// Shadow rays pass through glass, keeping its transmittance; off when a caustic photon
  /// map brings that light instead (glass then shadows like any object).
  bool transmissive_shadows = true;
};

/// Whitted's recursion as CS 488 and the original project define it: local Phong shading
/// with shadow rays at every hit, plus the light arriving along each material's specular
/// lobes, to -r reflections and -f refractions deep; a lobe past its limit ends in one
/// straight look along it (terminal_light) rather than black. Shadow rays pass through
/// transmissive surfaces (shadow_transmittance.h). Asks materials and lights; names none.
/// An IndirectLight, when given, adds its light at every surface shaded.
class WhittedIntegrator final : public Integrator {
 public:
  /// `regions`, the accelerator's region search where it has one, lets an area light's shadow
  /// rays test only what can stand in their way.
  WhittedIntegrator(const World& world, const Accelerator& accel, IntegratorSettings settings,
                    const IndirectLight* indirect = nullptr, const RegionSearch* regions = nullptr)
      : world_(world), accel_(accel), shadow_queries_{accel, regions}, settings_(settings), indirect_(indirect) {}

  Color radiance(const Ray& ray, RandomStream& random, TraceState& state) const override;

 private:
  /// The path a ray ends: its bounces of each kind so far (for the -r and -f limits), and the
  /// weight its colour will have in the pixel (the product of the lobe weights along it).
  struct RayPath {
    int reflections = 0;
    int refractions = 0;
    float weight = 1;

    RayPath after(LobeKind kind, float factor) const {
      return kind == LobeKind::kReflection ? RayPath{reflections + 1, refractions, weight * factor}
                                           : RayPath{reflections, refractions + 1, weight * factor};
    }
  };

  Color trace(const Ray& ray, RayPath path, RandomStream& random, TraceState& state) const;
  /// ambient⊙kd + Σ lights (kd·max(0,n·l) + ks·max(0,r·v)^shininess)·I·att, with shadows.
  Color direct_light(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading& local,
                     RandomStream& random, TraceState& state) const;
  /// Direct light plus what the IndirectLight adds there; `weight` is the surface's share in
  /// its pixel.
  Color surface_light(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading& local,
                      float weight, RandomStream& random, TraceState& state) const;
  /// The Phong reflection of one light sample, times the share of it that `visibility` says
  /// arrives; black when the light is behind the surface. Asks for visibility only where the
  /// surface reflects some of the sample.
  Color light_sample(const ShadingFrame& frame, const LocalShading& local, const LightSample& sample,
                     const Point3& point, LightVisibility& visibility) const;
  /// Light arriving along the material's specular lobes, within the depth limits.
  Color specular_light(const SurfaceInteraction& si, const ShadingFrame& frame, const SpecularLobes& lobes,
                       RayPath path, RandomStream& random, TraceState& state) const;
  /// The mean of a glossy lobe's rays over its cone.
  Color glossy_light(const SurfaceInteraction& si, const ShadingFrame& frame, const SpecularLobe& lobe,
                     RayPath next, RandomStream& random, TraceState& state) const;
  /// What a lobe past the -r/-f limit brings: the ray goes on straight through transmissive
  /// surfaces (keeping their shadow transmittance) to the first opaque one, and returns its
  /// local shading (ambient and direct light, no further lobes), or the background.
  Color terminal_light(const SurfaceInteraction& si, const Vector3& direction, float weight, RandomStream& random,
                       TraceState& state) const;
  /// The light arriving along a secondary ray leaving si.
  Color trace_secondary(const SurfaceInteraction& si, const Vector3& direction, RayPath path,
                        RandomStream& random, TraceState& state) const;
  int depth_limit(LobeKind kind) const {
    return kind == LobeKind::kReflection ? settings_.max_reflection_depth : settings_.max_refraction_depth;
  }
  bool within_depth(LobeKind kind, const RayPath& path) const {
    return (kind == LobeKind::kReflection ? path.reflections : path.refractions) < depth_limit(kind);
  }

  const World& world_;
  const Accelerator& accel_;
  ShadowQueries shadow_queries_;
  IntegratorSettings settings_;
  const IndirectLight* indirect_;
};

}  // namespace mjray
