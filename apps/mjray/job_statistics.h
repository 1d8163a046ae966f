#pragma once
/// The statistics of one gr.render job, printed at the end and written by --stats-json.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mjray/integrator/photon/photon_statistics.h"
#include "mjray/render/image_render.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// What one MPI rank did for a job (mjray-mpi); the job's own figures are the totals.
struct RankStatistics {
  int rank = 0;
  std::string host;
  int threads = 0;
  double seconds_load = 0;       ///< running the scene script on this rank
  double seconds_build = 0;      ///< flattening and building the accelerator on this rank
  double seconds_rendering = 0;  ///< thread-seconds spent rendering tiles, pixels or frames
  uint64_t tiles = 0;            ///< first-pass tiles rendered
  uint64_t pixels_supersampled = 0;
  uint64_t rays = 0;
  uint64_t bytes_sent = 0;       ///< message bytes this rank sent for the job
};

/// Everything the user is told about one render.
struct JobStatistics {
  std::string image;
  double seconds_parse = 0;
  double seconds_build = 0;
  double seconds_render = 0;
  uint32_t primitives = 0;
  std::string accel;
  int grid_resolution = 0;  ///< voxels per axis of --accel grid; 0 for other accelerators
  RenderStats render;
  uint64_t peak_rss_bytes = 0;
  std::optional<PhotonStatistics> photons;  ///< with --caustics or --gi
  std::vector<RankStatistics> ranks;  ///< under MPI: each rank that took part

  double seconds_photons() const { return photons ? photons->seconds() : 0; }
  double seconds_total() const { return seconds_parse + seconds_build + seconds_photons() + seconds_render; }
  double rays_per_second() const;
};

/// The process's peak resident memory so far.
uint64_t peak_rss_bytes();

/// The one-paragraph summary printed after a render.
std::string summary_text(const JobStatistics& s);

/// The line printed after each frame of an animation: "mjray: wrote FILE (frame 7/24, 0.84s)",
/// or with `detailed` (--stats) the frame's times, rays and memory on that line.
std::string frame_line(const JobStatistics& s, const std::string& frame, bool detailed);

/// What an animation's frames rendered in this run add up to (the script parsed once):
/// "mjray: rendered 24 frames (2 kept) in 12.3s", or with `detailed` the paragraph of
/// summary_text over all of them.
std::string animation_summary(const std::vector<JobStatistics>& frames, size_t kept, bool detailed);

}  // namespace mjray
