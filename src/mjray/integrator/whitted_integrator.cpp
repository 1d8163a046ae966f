#include "mjray/integrator/whitted_integrator.h"

#include <cmath>

#include "mjray/integrator/spawn_ray.h"

namespace mjray {

Color WhittedIntegrator::radiance(const Ray& ray, RayCounters& counters) const {
  ++counters.primary;
  return trace(ray, Depth{}, counters);
}

Color WhittedIntegrator::trace(const Ray& ray, Depth depth, RayCounters& counters) const {
  const auto hit = accel_.intersect(ray, kInfinity);
  if (!hit) return world_.background_radiance(ray.direction);
  const SurfaceInteraction si = world_.interaction(ray, *hit);
  const Material& material = world_.materials[si.material];
  // Shade with the normal that faces the viewer.
  const Vector3 wo = normalize(-ray.direction);
  const Normal3 n = face_forward(si.shading_normal, wo);
  return direct_light(si, n, wo, material, counters) +
         secondary_light(si, n, wo, material, depth, counters);
}

Color WhittedIntegrator::direct_light(const SurfaceInteraction& si, const Normal3& n,
                                      const Vector3& wo, const Material& material,
                                      RayCounters& counters) const {
  const PhongMaterial& phong = phong_of(material);
  Color result = world_.ambient * phong.kd;
  for (const Light& light : world_.lights) {
    const PointLight& point = std::get<PointLight>(light);
    const Vector3 to_light = point.position - si.point;
    const float distance = length(to_light);
    if (!(distance > 0)) continue;
    const Vector3 l = to_light / distance;
    const float n_dot_l = dot(n, l);
    if (n_dot_l <= 0) continue;  // the light is behind the surface
    ++counters.shadow;
    if (accel_.occluded(spawn_ray_to(si, point.position), kShadowTMax)) continue;
    // Phong's mirror direction r of the light about n, compared with the view direction.
    const Vector3 r = Vector3(n) * (2 * n_dot_l) - l;
    const float r_dot_v = std::max(0.f, dot(r, wo));
    const Color reflectance = phong.kd * n_dot_l + phong.ks * std::pow(r_dot_v, phong.shininess);
    result += reflectance * point.colour * point.attenuation(distance);
  }
  return result;
}

Color WhittedIntegrator::secondary_light(const SurfaceInteraction&, const Normal3&,
                                         const Vector3&, const Material&, Depth,
                                         RayCounters&) const {
  return {};
}

}  // namespace mjray
