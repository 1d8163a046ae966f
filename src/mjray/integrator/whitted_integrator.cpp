#include "mjray/integrator/whitted_integrator.h"

#include <cmath>

#include "mjray/core/sampling.h"
#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/shadow_transmittance.h"
#include "mjray/integrator/unreflected_light.h"

namespace mjray {

namespace {

/// Random values an area-light sample draws: its jitter in s and in t.
constexpr uint64_t kDrawsPerLightSample = 2;

}  // namespace

Color WhittedIntegrator::radiance(const Ray& ray, RandomStream& random, TraceState& state) const {
  ++state.rays.primary;
  return trace(ray, Depth{}, random, state);
}

Color WhittedIntegrator::trace(const Ray& ray, Depth depth, RandomStream& random,
                               TraceState& state) const {
  const auto found = closest_surface(world_, accel_, ray);
  if (!found) return world_.background_radiance(ray.direction);
  const SurfaceInteraction& si = *found;
  const Material& material = world_.materials[si.material];
  // Shade with the normal that faces the viewer.
  const Vector3 wo = normalize(-ray.direction);
  const ShadingFrame frame{wo, face_forward(si.shading_normal, wo), si.geometric_normal};
  // A texture replaces kd here: evaluated once for all lights.
  const LocalShading local = local_shading(material, si);
  // The specular lobes draw their samples first, then direct light: the order is part of
  // the image.
  const Color specular = specular_light(si, frame, specular_lobes(material, frame), depth, random, state);
  return surface_light(si, frame, local, depth.weight, random, state) + specular;
}

Color WhittedIntegrator::surface_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                       const LocalShading& local, float weight, RandomStream& random,
                                       TraceState& state) const {
  const Color direct = direct_light(si, frame, local, random, state);
  return indirect_ ? direct + indirect_->radiance(si, frame, local, weight, random, state.rays) : direct;
}

Color WhittedIntegrator::direct_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                      const LocalShading& local, RandomStream& random,
                                      TraceState& state) const {
  Color result = local.ambient(world_.ambient);
  for (size_t index = 0; index < world_.lights.size(); ++index) {
    const Light& light = world_.lights[index];
    // Compute the mean over the light's N×N jittered grid (its centre when N = 1, which
    // gives an area light the hard shadow of a point light there).
    const int n = std::max(1, samples_per_axis(light, settings_.area_light_samples));
    if (reflects_none_of(local, frame, si.point, light)) {
      // Its samples would add exactly zero (+0, which also turns a −0 ambient into +0); their
      // jitter is passed over so that later draws stay the same.
      result += Color{};
      if (n > 1) random.skip(kDrawsPerLightSample * uint64_t(n * n));
      continue;
    }
    if (n == 1) {
      DeferredShadowScope scope(accel_);
      result += light_sample(si, frame, local, sample_li(light, si.point, {0.5f, 0.5f}), index, state, scope);
      continue;
    }
    // Found once for all n×n samples (when one first needs a shadow ray): what their shadow
    // rays can hit, if anything.
    DeferredShadowScope scope(world_.primitives, accel_, si, light, state.occluders.slot(index));
    Color sum;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // A sample's kDrawsPerLightSample draws: its jitter in s, then in t.
        const float jitter_s = random.uniform();
        const float jitter_t = random.uniform();
        const Point2 u{(float(i) + jitter_s) / float(n), (float(j) + jitter_t) / float(n)};
        sum += light_sample(si, frame, local, sample_li(light, si.point, u), index, state, scope);
      }
    result += sum / float(n * n);
  }
  return result;
}

Color WhittedIntegrator::light_sample(const SurfaceInteraction& si, const ShadingFrame& frame,
                                      const LocalShading& local, const LightSample& sample,
                                      size_t light_index, TraceState& state, DeferredShadowScope& deferred) const {
  const Vector3 to_light = sample.position - si.point;
  const float distance = sample.distance;  // length(to_light), found by the light
  if (!(distance > 0)) return {};
  const Vector3 l = to_light / distance;
  const float n_dot_l = dot(frame.n, l);
  if (n_dot_l <= 0) return {};  // the light is behind the surface
  // What the surface would not reflect needs no shadow ray: without a diffuse part, a
  // glass's narrow highlight is exactly zero (the power underflows) for most of an area
  // light's samples. Elsewhere the term is computed only for samples that reach the light.
  const auto unshadowed = [&] { return local.phong(frame, l, n_dot_l) * sample.intensity; };
  if (local.kd.is_black() && unshadowed().is_black()) return {};
  const ShadowScope& scope = deferred.get();
  if (scope.clear()) return unshadowed();
  ++state.rays.shadow;
  // spawn_ray_to's ray, its origin found once for all of the light's samples where it can be.
  const Point3* origin = scope.shared_origin();
  const Ray shadow = origin ? ray_to(*origin, sample.position) : spawn_ray_to(si, sample.position);
  // The primitive that blocked the last shadow ray toward this light mostly blocks this one
  // (a scope's list already holds it first).
  uint32_t* cached = state.occluders.slot(light_index);
  if (cached && *cached != OccluderCache::kNone && scope.whole_scene() &&
      world_.primitives.intersect(*cached, shadow, {0, kShadowTMax}))
    return {};
  const Accelerator& occluders = scope.occluders();
  // With a caustic photon map glass shadows like any object: the map brings its light.
  if (!settings_.transmissive_shadows && world_.primitives.any_transmissive()) {
    if (occluders.occluded(shadow, kShadowTMax)) return {};
    return unshadowed();
  }
  // Through glass: what the transmissive surfaces on the way let pass.
  const ShadowResult through = shadow_ray_transmittance(world_, occluders, shadow, kShadowTMax);
  if (through.blocker && cached) *cached = *through.blocker;
  if (through.kept.is_black()) return {};
  if (!world_.primitives.any_transmissive()) return unshadowed();
  return unshadowed() * through.kept;
}

Color WhittedIntegrator::trace_secondary(const SurfaceInteraction& si, const Vector3& direction,
                                         Depth depth, RandomStream& random,
                                         TraceState& state) const {
  // Adaptive depth control: a ray whose colour would change the pixel by less than half an
  // 8-bit step is not worth tracing. Without it, glass that both reflects and refracts at
  // every hit grows a binary tree of 2^(r+f) rays.
  constexpr float kMinWeight = 0.5f / 255;
  if (depth.weight < kMinWeight) return {};
  ++state.rays.secondary;
  return trace(spawn_ray(si, direction), depth, random, state);
}

Color WhittedIntegrator::specular_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                        const SpecularLobes& lobes, Depth depth, RandomStream& random,
                                        TraceState& state) const {
  Color result;
  for (const SpecularLobe& lobe : lobes) {
    const Depth next = depth.after(lobe.kind, lobe.weight);
    // Past the depth limit a lobe still shows what lies along it, never black; a limit of 0
    // turns that kind of lobe off.
    if (!within_depth(lobe.kind, depth)) {
      if (depth_limit(lobe.kind) > 0)
        result += lobe.weight * terminal_light(si, lobe.direction, next.weight, random, state);
      continue;
    }
    // A glossy lobe blurs only the first reflection (as the original): deeper ones are mirrors.
    if (lobe.cos_cone < 1 && depth.reflection == 0)
      result += glossy_light(si, frame, lobe, next, random, state);
    else
      result += lobe.weight * trace_secondary(si, lobe.direction, next, random, state);
  }
  return result;
}

Color WhittedIntegrator::terminal_light(const SurfaceInteraction& origin, const Vector3& direction, float weight,
                                        RandomStream& random, TraceState& state) const {
  constexpr float kMinWeight = 0.5f / 255;  // as trace_secondary's adaptive depth control
  constexpr int kMaxCrossings = 16;
  Color kept{1, 1, 1}, result;
  SurfaceInteraction from = origin;
  for (int crossing = 0; crossing < kMaxCrossings && weight * kept.max_component() >= kMinWeight; ++crossing) {
    ++state.rays.secondary;
    const Ray ray = spawn_ray(from, direction);
    const auto found = closest_surface(world_, accel_, ray);
    if (!found) return result + kept * world_.background_radiance(direction);
    const Material& material = world_.materials[found->material];
    const Vector3 wo = normalize(-direction);
    const ShadingFrame frame{wo, face_forward(found->shading_normal, wo), found->geometric_normal};
    result += kept * surface_light(*found, frame, local_shading(material, *found), weight * kept.max_component(),
                                   random, state);
    if (!transmissive(material)) break;
    kept = kept * shadow_transmittance(material, frame);
    from = *found;
  }
  return result;
}

Color WhittedIntegrator::glossy_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                      const SpecularLobe& lobe, Depth next, RandomStream& random,
                                      TraceState& state) const {
  Color sum;
  const int samples = lobe.samples;
  for (int k = 0; k < samples; ++k) {
    // Stratify u1 into `samples` strata; pair them with a jittered golden-ratio sequence.
    const float u1 = (float(k) + random.uniform()) / float(samples);
    const float u2 = std::fmod(float(k) * 0.618033988749895f + random.uniform() / float(samples), 1.f);
    Vector3 d = sample_cone(lobe.direction, lobe.cos_cone, u1, u2);
    // A direction below the surface falls back to the lobe's axis.
    if (dot(d, si.geometric_normal) * dot(frame.wo, si.geometric_normal) <= 0) d = lobe.direction;
    sum += trace_secondary(si, d, next, random, state);
  }
  return lobe.weight * sum / float(samples);
}

}  // namespace mjray
