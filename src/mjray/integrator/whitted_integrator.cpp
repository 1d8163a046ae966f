#include "mjray/integrator/whitted_integrator.h"

#include <cmath>

#include "mjray/core/sampling.h"
#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/shadow_transmittance.h"
#include "mjray/integrator/reflection_bound.h"

namespace mjray {

namespace {

/// Random values an area-light sample draws: its jitter in s and in t.
constexpr uint64_t kDrawsPerLightSample = 2;

}  // namespace

Color WhittedIntegrator::radiance(const Ray& ray, RandomStream& random, TraceState& state) const {
  ++state.rays.primary;
  return trace(ray, RayPath{}, random, state);
}

Color WhittedIntegrator::trace(const Ray& ray, RayPath path, RandomStream& random,
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
  const Color specular = specular_light(si, frame, specular_lobes(material, frame), path, random, state);
  return surface_light(si, frame, local, path.weight, random, state) + specular;
}

Color WhittedIntegrator::surface_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                       const LocalShading& local, float weight, RandomStream& random,
                                       TraceState& state) const {
  const Color direct = direct_light(si, frame, local, random, state);
  return indirect_ ? direct + indirect_->radiance(si, frame, local, weight, random, state) : direct;
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
    if (!may_reflect(local, frame, si.point, light)) {
      // Its samples would add exactly zero (+0, which also turns a −0 ambient into +0); their
      // jitter is passed over so that later draws stay the same.
      result += Color{};
      if (n > 1) random.skip(kDrawsPerLightSample * uint64_t(n * n));
      continue;
    }
    LightVisibility visibility(world_, shadow_queries_, si, light, index, n > 1, settings_.transmissive_shadows, state);
    if (n == 1) {
      result += light_sample(frame, local, sample_li(light, si.point, {0.5f, 0.5f}), si.point, visibility);
      continue;
    }
    Color sum;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // A sample's kDrawsPerLightSample draws: its jitter in s, then in t.
        const float jitter_s = random.uniform();
        const float jitter_t = random.uniform();
        const Point2 u{(float(i) + jitter_s) / float(n), (float(j) + jitter_t) / float(n)};
        sum += light_sample(frame, local, sample_li(light, si.point, u), si.point, visibility);
      }
    result += sum / float(n * n);
  }
  return result;
}

Color WhittedIntegrator::light_sample(const ShadingFrame& frame, const LocalShading& local, const LightSample& sample,
                                      const Point3& point, LightVisibility& visibility) const {
  const float distance = sample.distance;  // length(sample.position - point), found by the light
  if (!(distance > 0)) return {};
  const Vector3 l = (sample.position - point) / distance;
  const float n_dot_l = dot(frame.n, l);
  if (n_dot_l <= 0) return {};  // the light is behind the surface
  if (sample.intensity.is_black()) return {};  // outside a spot's cone: nothing to shadow
  // What the surface would not reflect needs no shadow ray: without a diffuse part, a
  // glass's narrow highlight is exactly zero (the power underflows) for most of an area
  // light's samples. Elsewhere the term is computed only for samples that arrive.
  const auto reflected = [&] { return local.phong(frame, l, n_dot_l) * sample.intensity; };
  if (local.kd.is_black() && reflected().is_black()) return {};
  const Color arriving = visibility.transmittance(sample.position);
  if (arriving.is_black()) return {};
  return reflected() * arriving;
}

Color WhittedIntegrator::trace_secondary(const SurfaceInteraction& si, const Vector3& direction,
                                         RayPath path, RandomStream& random,
                                         TraceState& state) const {
  // Adaptive depth control: a ray whose colour would change the pixel by less than half an
  // 8-bit step is not worth tracing. Without it, glass that both reflects and refracts at
  // every hit grows a binary tree of 2^(r+f) rays.
  constexpr float kMinWeight = 0.5f / 255;
  if (path.weight < kMinWeight) return {};
  ++state.rays.secondary;
  return trace(spawn_ray(si, direction), path, random, state);
}

Color WhittedIntegrator::specular_light(const SurfaceInteraction& si, const ShadingFrame& frame,
                                        const SpecularLobes& lobes, RayPath path, RandomStream& random,
                                        TraceState& state) const {
  Color result;
  for (const SpecularLobe& lobe : lobes) {
    const RayPath next = path.after(lobe.kind, lobe.weight);
    // Past the depth limit a lobe still shows what lies along it, never black; a limit of 0
    // turns that kind of lobe off.
    if (!within_depth(lobe.kind, path)) {
      if (depth_limit(lobe.kind) > 0)
        result += lobe.weight * terminal_light(si, lobe.direction, next.weight, random, state);
      continue;
    }
    // A glossy lobe blurs only the first reflection (as the original): deeper ones are mirrors.
    if (lobe.cos_cone < 1 && path.reflections == 0)
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
                                      const SpecularLobe& lobe, RayPath next, RandomStream& random,
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
