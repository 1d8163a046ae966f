#include "statistics_json.h"

#include "mjray/io/atomic_file.h"

namespace mjray {

namespace {

/// The photon maps' figures, added to a job's object.
void add_photons(Json& out, const PhotonStatistics& p) {
  out["photons_caustic_emitted"] = p.caustic_emitted;
  out["photons_caustic_stored"] = p.caustic_stored;
  out["photons_global_emitted"] = p.global_emitted;
  out["photons_global_stored"] = p.global_stored;
  out["photon_irradiance_samples"] = p.irradiance_samples;
  out["photon_rays"] = p.rays;
  out["seconds_photons"] = p.seconds();
  out["seconds_photon_trace"] = p.seconds_trace;
  out["seconds_photon_build"] = p.seconds_build;
  out["seconds_photon_irradiance"] = p.seconds_irradiance;
  out["photon_map_bytes"] = p.memory_bytes;
}

/// What one MPI rank did for a job.
Json rank_object(const RankStatistics& r) {
  return {{"rank", r.rank},
          {"threads", r.threads},
          {"seconds_load", r.seconds_load},
          {"seconds_build", r.seconds_build},
          {"seconds_rendering", r.seconds_rendering},
          {"tiles", r.tiles},
          {"pixels_supersampled", r.pixels_supersampled},
          {"rays", r.rays},
          {"bytes_sent", r.bytes_sent},
          {"host", r.host}};
}

}  // namespace

Json statistics_object(const JobStatistics& s) {
  Json out = {{"image", s.image},
              {"accel", s.accel},
              {"seconds_total", s.seconds_total()},
              {"seconds_parse", s.seconds_parse},
              {"seconds_build", s.seconds_build},
              {"seconds_render", s.seconds_render},
              {"primitives", s.primitives},
              {"threads", s.render.threads},
              {"rays_primary", s.render.rays.primary},
              {"rays_secondary", s.render.rays.secondary},
              {"rays_shadow", s.render.rays.shadow},
              {"rays_per_second", s.rays_per_second()},
              {"pixels_supersampled", s.render.pixels_supersampled},
              {"peak_rss_bytes", s.peak_rss_bytes},
              {"grid_resolution", s.grid_resolution}};
  if (s.render.subdivided) out["antialias_method"] = "subdivide";  // pixels_supersampled is then 0
  if (s.render.refined_to_noise) out["noise_target"] = true;  // pixels_supersampled counts refinements
  if (s.photons) add_photons(out, *s.photons);
  if (!s.ranks.empty()) {
    Json ranks = Json::array();
    for (const RankStatistics& r : s.ranks) ranks.push_back(rank_object(r));
    out["ranks"] = std::move(ranks);
  }
  return out;
}

std::string json_text(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path) {
  std::string out = "[\n";
  for (size_t i = 0; i < jobs.size(); ++i) out += "  " + json_text(statistics_object(jobs[i])) + (i + 1 < jobs.size() ? ",\n" : "\n");
  write_file_atomically(path, out + "]\n");
}

}  // namespace mjray
