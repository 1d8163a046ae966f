#include "mjray/integrator/photon/photon_light.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/photon/path_choice.h"

namespace mjray {

namespace {

constexpr int kMaxGatherBounces = 8;  ///< specular bounces of a gather ray before it gives up

}  // namespace

Color PhotonMappedLight::radiance(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading& local,
                                  float weight, RandomStream& random, TraceState& state) const {
  Color result;
  // Each camera sample reads its own pass of the caustic map, in turn.
  if (maps_.caustic_passes() > 0 && !local.kd.is_black()) {
    const size_t pass = state.camera_sample % maps_.caustic_passes();
    if (!maps_.caustic(pass).empty())
      result += local.kd * irradiance_estimate(maps_.caustic(pass), si.point, frame.n, maps_.caustic_query(pass));
  }
  if (!maps_.irradiance().empty()) result += final_gather(si, frame, weight, random, state.rays);
  return result;
}

Color PhotonMappedLight::final_gather(const SurfaceInteraction& si, const ShadingFrame& frame, float weight,
                                      RandomStream& random, RayCounters& counters) const {
  const LocalShading brdf = scattering(world_.materials[si.material], si);
  if (brdf.kd.is_black() && brdf.ks.is_black()) return {};
  // An m×m jittered grid of rays (m² about gather_rays × weight); u1 also splits the rays
  // between the BRDF's two parts in proportion.
  const float wanted = float(settings_.gather_rays) * std::clamp(weight, 0.f, 1.f);
  const int m = std::max(1, int(std::lround(std::sqrt(wanted))));
  const int rays = m * m;
  Color sum;
  for (int k = 0; k < rays; ++k) {
    const float u1 = (float(k % m) + random.uniform()) / float(m);
    const float u2 = (float(k / m) + random.uniform()) / float(m);
    const auto sample = brdf.sample(frame, u1, u2);
    // Nothing arrives from inside the surface (where a shading normal may point a ray).
    if (!sample || dot(sample->wi, frame.geometric_normal) * dot(frame.wo, frame.geometric_normal) <= 0) continue;
    const Color throughput = sample->f * (dot(sample->wi, frame.n) / sample->pdf);
    sum += throughput * gathered(spawn_ray(si, sample->wi), random, counters);
  }
  return sum / float(rays);
}

Color PhotonMappedLight::gathered(Ray ray, RandomStream& random, RayCounters& counters) const {
  Color result;
  for (int bounce = 0; bounce < kMaxGatherBounces; ++bounce) {
    ++counters.secondary;
    const auto hit = closest_surface(world_, accel_, ray);
    if (!hit) break;
    const Material& material = world_.materials[hit->material];
    const ShadingFrame frame = frame_facing(*hit, ray.direction);
    const Color kd = scattering(material, *hit).kd;
    if (!kd.is_black()) result += kd * stored_irradiance(hit->point, frame.n);
    const SpecularLobes lobes = specular_lobes(material, frame);
    if (lobes.empty()) break;
    const PathChoice choice = PathChoice::pick(lobes, 0, random.uniform());
    const float u1 = random.uniform(), u2 = random.uniform();
    if (!choice.lobe) break;
    ray = spawn_ray(*hit, lobe_direction(*choice.lobe, frame, u1, u2));
  }
  return result;
}

Color PhotonMappedLight::stored_irradiance(const Point3& p, const Normal3& n) const {
  std::array<Neighbour, 1> nearest;
  const float radius = maps_.global_query().max_radius;
  const auto near = maps_.irradiance().nearest(
      p, radius * radius, [&](const PackedNormal& normal) { return faces_alike(normal, n); }, nearest);
  return near.found.empty() ? Color{} : maps_.irradiance().items()[near.found[0].index].irradiance;
}

}  // namespace mjray
