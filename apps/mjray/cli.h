#pragma once
/// The mjray command line.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mjray/job/job_options.h"
#include "mjray/lua/scene_loader.h"

namespace mjray {

/// Everything the command line can say.
struct CommandLine {
  std::filesystem::path scene;
  int max_reflection_depth = 8;        // -r
  int max_refraction_depth = 8;        // -f
  std::optional<int> grid_size;        // -g
  bool optimal_grid = false;           // -o
  int area_light_samples = 1;          // -s
  int antialias_samples = 0;           // -a
  float antialias_threshold = 0.1f;    // --aa-threshold
  AntialiasMethod antialias_method = AntialiasMethod::kGrid;  // --aa-method
  std::string accel;                   // --accel; empty = decided by -g/-o or bvh
  int threads = 0;                     // -j
  std::optional<int> tile_size;        // --tile-size; default the renderer's
  std::optional<std::filesystem::path> output;  // --output
  std::optional<std::filesystem::path> outdir;  // --outdir
  bool print_stats = false;            // --stats
  std::optional<std::filesystem::path> stats_json;
  uint64_t seed = 0;
  bool quiet = false;
  bool resume = false;
  bool srgb = false;                   // --gamma srgb
  SceneLoadOptions load;               // also -D/--define: load.defines

  // Camera, image and animation.
  int samples_per_pixel = 1;           // --spp
  std::optional<float> aperture_radius;  // --aperture
  std::optional<float> focus_distance;   // --focus-distance
  std::optional<int> width, height;    // --size WxH
  std::optional<PixelRect> crop;       // --crop X0,Y0,X1,Y1
  std::optional<FrameRange> frames;    // --frames A-B:STEP
  std::optional<std::filesystem::path> video;  // --video
  int fps = 24;                        // --fps
  int bit_depth = 8;                   // --bit-depth
  int jpeg_quality = 90;               // --jpeg-quality

  // Photon mapping: photons emitted, 0 = off.
  uint64_t caustic_photons = 0;        // --caustics
  uint64_t global_photons = 0;         // --gi

  // The live preview (apps/mjray/watch/).
  bool watch = false;                  // --watch
  std::optional<int> port;             // --port; 0 = any free port; default kDefaultWatchPort
  std::optional<std::string> listen;   // --listen ADDR; default 127.0.0.1
  bool show_help = false;
  bool show_version = false;
  std::vector<std::string> warnings;   ///< options that change nothing with the others given
};

/// The port --watch serves on without --port (the next free one when it is taken).
inline constexpr int kDefaultWatchPort = 8488;

/// Thrown for a bad command line; main prints it with the usage hint and exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses argv with getopt's conventions (-s4, -s 4, grouped flags -og 5, --name=value, --
/// ends the options); throws UsageError.
CommandLine parse_command_line(const std::vector<std::string>& args);

/// The job options the command line asks for: --accel wins, then -o, then -g (0 = none), else
/// the BVH; sampling, outputs and encoding as given.
JobOptions job_options(const CommandLine& cl);

/// The --help text.
std::string usage_text();

}  // namespace mjray
