#pragma once
/// The statistics of one gr.render job, printed at the end and written by --stats-json.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mjray/integrator/photon/photon_statistics.h"
#include "mjray/render/image_render.h"

namespace mjray {

/// Everything the user is told about one render.
struct JobStatistics {
  std::string image;
  double seconds_parse = 0;
  double seconds_build = 0;
  double seconds_render = 0;
  uint32_t primitives = 0;
  std::string accel;
  RenderStats render;
  uint64_t peak_rss_bytes = 0;
  std::optional<PhotonStatistics> photons;  ///< with --caustics or --gi

  double seconds_photons() const { return photons ? photons->seconds() : 0; }
  double seconds_total() const { return seconds_parse + seconds_build + seconds_photons() + seconds_render; }
  double rays_per_second() const;
};

/// The process's peak resident memory so far.
uint64_t peak_rss_bytes();

/// The one-paragraph summary printed after a render.
std::string summary_text(const JobStatistics& s);

/// Writes the list of job statistics as a JSON array of objects. Throws OutputError.
void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path);

}  // namespace mjray
