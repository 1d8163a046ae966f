#pragma once
/// The statistics of one gr.render job, printed at the end and written by --stats-json.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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

  double seconds_total() const { return seconds_parse + seconds_build + seconds_render; }
  double rays_per_second() const;
};

/// The process's peak resident memory so far.
uint64_t peak_rss_bytes();

/// The one-paragraph summary printed after a render.
std::string summary_text(const JobStatistics& s);

/// `text` as a JSON string literal, quotes included.
std::string json_string(const std::string& text);

/// One job's statistics as a JSON object on one line (the elements of write_statistics_json).
std::string statistics_json(const JobStatistics& s);

/// Writes the list of job statistics as a JSON array of objects. Throws OutputError.
void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path);

}  // namespace mjray
