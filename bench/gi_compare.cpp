// mjray-gi-compare: final gathering from a global photon map against path-traced indirect
// light with next-event estimation, at equal render time, by their error against a
// path-traced reference of many paths. Prints one JSON line per render.
//
//   mjray-gi-compare SCENE.lua [--size W] [--reference-paths N] [--threads N]
//
// The image is rendered W pixels wide (same camera). Direct light is Whitted's in every
// render, so the renders differ only in the indirect term. Final gathering runs at several
// photon counts and gather rays; path tracing at several paths per pixel (each path: BRDF
// sampling, a shadow ray to every light at every vertex, Russian roulette after two bounces).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/indirect_light.h"
#include "mjray/integrator/photon/path_choice.h"
#include "mjray/integrator/shadow_transmittance.h"
#include "mjray/job/prepared_job.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/render/image_render.h"

namespace {

using namespace mjray;
using Clock = std::chrono::steady_clock;

/// Indirect light by path tracing: `paths` paths from the surface, next-event estimation at
/// each vertex, in the same units as the photon maps (a vertex of BRDF f lit with irradiance
/// E sends π·f·E, as the CS 488 diffuse term kd·E does).
class PathTracedLight final : public IndirectLight {
 public:
  PathTracedLight(const World& world, const Accelerator& accel, int paths) : world_(world), accel_(accel), paths_(paths) {}

  Color radiance(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading&, float,
                 RandomStream& random, TraceState& state) const override {
    RayCounters& counters = state.rays;
    const LocalShading brdf = scattering(world_.materials[si.material], si);
    if (brdf.kd.is_black() && brdf.ks.is_black()) return {};
    Color sum;
    for (int k = 0; k < paths_; ++k) {
      const float u1 = (float(k) + random.uniform()) / float(paths_), u2 = random.uniform();
      const auto sample = brdf.sample(frame, u1, u2);
      if (!sample) continue;
      sum += sample->f * (dot(sample->wi, frame.n) / sample->pdf) * path(spawn_ray(si, sample->wi), random, counters);
    }
    return sum / float(paths_);
  }

 private:
  Color path(Ray ray, RandomStream& random, RayCounters& counters) const {
    constexpr float kPi = std::numbers::pi_v<float>;
    Color result, throughput{1, 1, 1};
    for (int bounce = 0; bounce < 64; ++bounce) {
      ++counters.secondary;
      const auto hit = closest_surface(world_, accel_, ray);
      if (!hit) break;
      const Material& material = world_.materials[hit->material];
      const ShadingFrame frame = frame_facing(*hit, ray.direction);
      const LocalShading brdf = scattering(material, *hit);
      for (const Light& light : world_.lights) {
        const LightSample ls = sample_li(light, hit->point, {random.uniform(), random.uniform()});
        const Vector3 to = ls.position - hit->point;
        const float d = length(to);
        const Vector3 l = to / d;
        const float cos_l = dot(frame.n, l);
        if (!(cos_l > 0)) continue;
        ++counters.shadow;
        const Color kept = shadow_ray_transmittance(world_, accel_, spawn_ray_to(*hit, ls.position), kShadowTMax).kept;
        result += throughput * brdf.eval(frame, l) * ls.intensity * kept * (kPi * cos_l);
      }
      const float albedo = (brdf.kd + brdf.ks).max_component();
      const PathChoice choice = PathChoice::pick(specular_lobes(material, frame), albedo, random.uniform());
      const float u1 = random.uniform(), u2 = random.uniform();
      Vector3 next;
      if (choice.lobe) {
        next = lobe_direction(*choice.lobe, frame, u1, u2);
      } else if (choice.brdf) {
        const auto s = brdf.sample(frame, u1, u2);
        if (!s) break;
        throughput = throughput * s->f * (dot(s->wi, frame.n) / (s->pdf * albedo));
        next = s->wi;
      } else {
        break;
      }
      ray = spawn_ray(*hit, next);
    }
    return result;
  }

  const World& world_;
  const Accelerator& accel_;
  int paths_;
};

double rms_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels().size(); ++i) {
    const Color d = a.pixels()[i] - b.pixels()[i];
    sum += (double(d.r) * d.r + double(d.g) * d.g + double(d.b) * d.b) / 3;
  }
  return std::sqrt(sum / double(a.pixels().size()));
}

double mean_value(const Image& a) {
  double sum = 0;
  for (const Color& c : a.pixels()) sum += (double(c.r) + c.g + c.b) / 3;
  return sum / double(a.pixels().size());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: mjray-gi-compare SCENE.lua [--size W] [--reference-paths N] [--threads N]\n");
    return 2;
  }
  int width = 160, reference_paths = 1024, threads = 0;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--size") width = std::atoi(argv[i + 1]);
    else if (a == "--reference-paths") reference_paths = std::atoi(argv[i + 1]);
    else if (a == "--threads") threads = std::atoi(argv[i + 1]);
  }
  SceneDescription scene = load_scene(argv[1], {});
  RenderJob& job = scene.jobs.at(0);
  job.height = std::max(1, job.height * width / job.width);
  job.width = width;
  RenderSettings render;
  render.threads = threads;

  // Path tracing: the reference and the equal-time candidates, over a job without photons.
  JobOptions plain;
  plain.render = render;
  plain.photons.global_photons = 1;  // global illumination's rules (no ambient term), a map of nothing
  const PreparedJob base(scene, 0, plain);
  const auto path_traced = [&](int paths, double* seconds) {
    const PathTracedLight indirect(base.world(), base.accelerator(), paths);
    const WhittedIntegrator integrator(base.world(), base.accelerator(), plain.integrator, &indirect);
    const auto start = Clock::now();
    Image image = render_image(base.camera(), job.width, job.height, integrator, render);
    *seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return image;
  };
  double seconds = 0;
  const Image reference = path_traced(reference_paths, &seconds);
  std::printf("{\"render\": \"reference\", \"method\": \"path tracing\", \"paths\": %d, \"seconds\": %.2f, "
              "\"mean\": %.5f}\n", reference_paths, seconds, mean_value(reference));
  std::fflush(stdout);
  for (const int paths : {4, 8, 16, 32, 64}) {
    const Image image = path_traced(paths, &seconds);
    std::printf("{\"render\": \"candidate\", \"method\": \"path tracing\", \"paths\": %d, \"seconds\": %.3f, "
                "\"rms_error\": %.5f, \"mean\": %.5f}\n", paths, seconds, rms_difference(image, reference),
                mean_value(image));
    std::fflush(stdout);
  }
  for (const uint64_t photons : {50000, 100000, 200000, 400000}) {
    for (const int gather : {16, 36, 64, 144}) {
      JobOptions options;
      options.render = render;
      options.photons.global_photons = photons;
      options.photons.gather_rays = gather;
      const auto start = Clock::now();
      const PreparedJob prepared(scene, 0, options);
      const Image image = render_image(prepared.camera(), job.width, job.height, prepared.integrator(), render);
      seconds = std::chrono::duration<double>(Clock::now() - start).count();
      std::printf("{\"render\": \"candidate\", \"method\": \"final gather\", \"photons\": %llu, \"gather_rays\": %d, "
                  "\"seconds\": %.3f, \"photon_seconds\": %.3f, \"rms_error\": %.5f, \"mean\": %.5f}\n",
                  (unsigned long long)photons, gather, seconds, prepared.photon_statistics()->seconds(),
                  rms_difference(image, reference), mean_value(image));
      std::fflush(stdout);
    }
  }
  return 0;
}
