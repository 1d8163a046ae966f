#include "mjray/integrator/whitted_integrator.h"

#include <cmath>
#include <numbers>

#include "mjray/integrator/sampling.h"
#include "mjray/integrator/spawn_ray.h"
#include "mjray/material/optics.h"

namespace mjray {


Color WhittedIntegrator::radiance(const Ray& ray, RandomStream& random, RayCounters& counters) const {
  ++counters.primary;
  return trace(ray, Depth{}, random, counters);
}

Color WhittedIntegrator::trace(const Ray& ray, Depth depth, RandomStream& random,
                               RayCounters& counters) const {
  const auto hit = accel_.intersect(ray, kInfinity);
  if (!hit) return world_.background_radiance(ray.direction);
  const SurfaceInteraction si = world_.interaction(ray, *hit);
  const Material& material = world_.materials[si.material];
  // Shade with the normal that faces the viewer.
  const Vector3 wo = normalize(-ray.direction);
  const Normal3 n = face_forward(si.shading_normal, wo);
  return direct_light(si, n, wo, material, random, counters) +
         secondary_light(si, n, wo, material, depth, random, counters);
}

Color WhittedIntegrator::direct_light(const SurfaceInteraction& si, const Normal3& n,
                                      const Vector3& wo, const Material& material,
                                      RandomStream& random, RayCounters& counters) const {
  // A texture replaces kd at this hit: evaluate it once for all lights (the copy leaves the
  // texture pointer behind, so threads do not contend on its reference count).
  const PhongMaterial& base = phong_of(material);
  const PhongMaterial phong{base.kd_at(si.object_point, si.uv), base.ks, base.shininess};
  Color result = world_.ambient * phong.kd;
  for (const Light& light : world_.lights) {
    if (const auto* point = std::get_if<PointLight>(&light)) {
      const float distance = length(point->position - si.point);
      result += light_sample(si, n, wo, phong, point->position, point->colour * point->attenuation(distance), counters);
      continue;
    }
    // Compute the mean over an N×N jittered grid on the area light (its centre when N = 1,
    // which gives the hard shadow of a point light there).
    const auto& area = std::get<AreaLight>(light);
    const int samples = std::max(1, settings_.area_light_samples);
    Color sum;
    for (int j = 0; j < samples; ++j)
      for (int i = 0; i < samples; ++i) {
        const float jitter_s = samples == 1 ? 0.5f : random.uniform();
        const float jitter_t = samples == 1 ? 0.5f : random.uniform();
        const Point3 p = area.point_at((float(i) + jitter_s) / float(samples), (float(j) + jitter_t) / float(samples));
        sum += light_sample(si, n, wo, phong, p, area.colour * area.attenuation(length(p - si.point)), counters);
      }
    result += sum / float(samples * samples);
  }
  return result;
}

Color WhittedIntegrator::light_sample(const SurfaceInteraction& si, const Normal3& n,
                                      const Vector3& wo, const PhongMaterial& phong,
                                      const Point3& light_point, const Color& intensity,
                                      RayCounters& counters) const {
  const Vector3 to_light = light_point - si.point;
  const float distance = length(to_light);
  if (!(distance > 0)) return {};
  const Vector3 l = to_light / distance;
  const float n_dot_l = dot(n, l);
  if (n_dot_l <= 0) return {};  // the light is behind the surface
  ++counters.shadow;
  if (accel_.occluded(spawn_ray_to(si, light_point), kShadowTMax)) return {};
  // Phong's mirror direction r of the light about n, compared with the view direction.
  const Vector3 r = Vector3(n) * (2 * n_dot_l) - l;
  const float r_dot_v = std::max(0.f, dot(r, wo));
  return (phong.kd * n_dot_l + phong.ks * std::pow(r_dot_v, phong.shininess)) * intensity;
}

Color WhittedIntegrator::trace_secondary(const SurfaceInteraction& si, const Vector3& direction,
                                         Depth depth, RandomStream& random,
                                         RayCounters& counters) const {
  // Adaptive depth control: a ray whose colour would change the pixel by less than half an
  // 8-bit step is not worth tracing. Without it, glass that both reflects and refracts at
  // every hit grows a binary tree of 2^(r+f) rays.
  constexpr float kMinWeight = 0.5f / 255;
  if (depth.weight < kMinWeight) return {};
  ++counters.secondary;
  return trace(spawn_ray(si, direction), depth, random, counters);
}

template <class ReflectanceFunction>
Color WhittedIntegrator::dielectric_light(const SurfaceInteraction& si, const Normal3& n,
                                          const Vector3& wo, float eta_outside, float eta_inside,
                                          ReflectanceFunction kr_of_cosine, Depth depth,
                                          RandomStream& random, RayCounters& counters) const {
  // Entering or leaving is decided by the geometric normal, which points out of the object.
  const bool entering = dot(wo, si.geometric_normal) > 0;
  const float eta_i = entering ? eta_outside : eta_inside;
  const float eta_t = entering ? eta_inside : eta_outside;
  const float cos_i = dot(wo, n);
  float kr = kr_of_cosine(cos_i, eta_i, eta_t);
  const auto transmitted = refract(wo, n, eta_i / eta_t);
  if (!transmitted) kr = 1;  // total internal reflection: the refracted share reflects
  Color result;
  if (kr > 0 && depth.reflection < settings_.max_reflection_depth)
    result += kr * trace_secondary(si, reflect(wo, n), depth.reflected(kr), random, counters);
  if (kr < 1 && depth.refraction < settings_.max_refraction_depth)
    result += (1 - kr) * trace_secondary(si, *transmitted, depth.refracted(1 - kr), random, counters);
  return result;
}

Color WhittedIntegrator::secondary_light(const SurfaceInteraction& si, const Normal3& n,
                                         const Vector3& wo, const Material& material, Depth depth,
                                         RandomStream& random, RayCounters& counters) const {
  const bool may_reflect = depth.reflection < settings_.max_reflection_depth;
  if (const auto* m = std::get_if<ReflectiveMaterial>(&material)) {
    if (!may_reflect || m->reflectivity <= 0) return {};
    return m->reflectivity * trace_secondary(si, reflect(wo, n), depth.reflected(m->reflectivity), random, counters);
  }
  if (const auto* m = std::get_if<RefractiveMaterial>(&material)) {
    const float kr = m->reflectivity;
    return dielectric_light(si, n, wo, m->eta_outside, m->eta_inside,
                            [kr](float, float, float) { return kr; }, depth, random, counters);
  }
  if (const auto* m = std::get_if<FresnelMaterial>(&material)) {
    return dielectric_light(si, n, wo, m->eta_outside, m->eta_inside, fresnel_dielectric, depth, random, counters);
  }
  if (const auto* m = std::get_if<GlossyMaterial>(&material)) {
    if (!may_reflect || m->reflectivity <= 0) return {};
    const Vector3 mirror = reflect(wo, n);
    const Depth reflected = depth.reflected(m->reflectivity);
    // Blur only the first reflection (as the original): deeper ones are plain mirrors.
    if (depth.reflection > 0 || m->samples <= 1)
      return m->reflectivity * trace_secondary(si, mirror, reflected, random, counters);
    Color sum;
    const float cos_max = m->cos_cone_angle();
    for (int k = 0; k < m->samples; ++k) {
      // Stratify u1 into `samples` strata; pair them with a jittered golden-ratio sequence.
      const float u1 = (float(k) + random.uniform()) / float(m->samples);
      const float u2 = std::fmod(float(k) * 0.618033988749895f + random.uniform() / float(m->samples), 1.f);
      Vector3 d = sample_cone(mirror, cos_max, u1, u2);
      if (dot(d, si.geometric_normal) * dot(wo, si.geometric_normal) <= 0) d = mirror;  // below the surface
      sum += trace_secondary(si, d, reflected, random, counters);
    }
    return m->reflectivity * sum / float(m->samples);
  }
  return {};  // PhongMaterial: local shading only
}

}  // namespace mjray
