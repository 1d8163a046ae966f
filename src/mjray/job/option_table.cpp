#include "mjray/job/option_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <system_error>
#include <tuple>
#include <utility>

#include <arpa/inet.h>

#include "mjray/core/image.h"
#include "mjray/core/parallel_for.h"

namespace mjray {

namespace {

// --- values --------------------------------------------------------------------------------

long long parse_integer(const std::string& option, const std::string& text, long long lo, long long hi) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
    throw UsageError(option + " expects a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got '" + text + "'");
  return value;
}

/// "BYTES", "NNKiB", "NNMiB" or "NNGiB" (also "K", "M", "G", "KB", "MB", "GB", all binary).
size_t parse_bytes(const std::string& option, const std::string& text) {
  const std::string usage = option + " expects a size like 512MiB, 4GiB or a number of bytes, got '" + text + "'";
  unsigned long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end == text.data()) throw UsageError(usage);
  std::string suffix(end, text.data() + text.size());
  for (char& c : suffix) c = char(std::toupper(static_cast<unsigned char>(c)));
  int shift = 0;
  if (suffix.empty() || suffix == "B") shift = 0;
  else if (suffix == "K" || suffix == "KB" || suffix == "KIB") shift = 10;
  else if (suffix == "M" || suffix == "MB" || suffix == "MIB") shift = 20;
  else if (suffix == "G" || suffix == "GB" || suffix == "GIB") shift = 30;
  else throw UsageError(usage);
  if (value > (std::numeric_limits<unsigned long long>::max() >> shift) >> 1) throw UsageError(usage);
  const unsigned long long bytes = value << shift;
  constexpr unsigned long long kMinimum = 1 << 20;
  if (bytes != 0 && bytes < kMinimum) throw UsageError(option + " must be at least 1MiB (or 0 for no limit), got '" + text + "'");
  return size_t(bytes);
}

/// A photon count: a whole number written plainly or in exponent form ("1e6"), 0 to 10⁹.
uint64_t parse_photon_count(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= 0 && value <= 1e9) || value != std::floor(value))
    throw UsageError(option + " expects a number of photons from 0 to 1e9 (e.g. 200000 or 1e6), got '" + text + "'");
  return uint64_t(value);
}

/// A number in (lo, hi].
double parse_real(const std::string& option, const std::string& text, double lo, double hi, const std::string& expected) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > lo && value <= hi))
    throw UsageError(option + " expects " + expected + ", got '" + text + "'");
  return value;
}

/// A finite number of at least 0.
double parse_at_least_zero(const std::string& option, const std::string& text, const std::string& expected) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= 0) || !std::isfinite(value))
    throw UsageError(option + " expects " + expected + ", got '" + text + "'");
  return value;
}

/// The whole numbers of `text` separated by `separator`, exactly `count` of them.
std::vector<long long> parse_integers(const std::string& text, char separator, size_t count, const std::string& usage) {
  std::vector<long long> values;
  size_t start = 0;
  while (true) {
    const size_t end = std::min(text.find(separator, start), text.size());
    long long value = 0;
    const auto [stop, ec] = std::from_chars(text.data() + start, text.data() + end, value);
    if (ec != std::errc() || stop != text.data() + end || end == start) throw UsageError(usage);
    values.push_back(value);
    if (end == text.size()) break;
    start = end + 1;
  }
  if (values.size() != count) throw UsageError(usage);
  return values;
}

/// --size WxH: whole numbers from 1 to kMaxImageSide, at most kMaxImagePixels pixels.
std::pair<int, int> parse_size(const std::string& option, const std::string& text) {
  const std::string usage = option + " expects WIDTHxHEIGHT with whole numbers from 1 to " + std::to_string(kMaxImageSide) +
                            " (e.g. 640x360), got '" + text + "'";
  const auto wh = parse_integers(text, 'x', 2, usage);
  if (wh[0] < 1 || wh[1] < 1 || wh[0] > kMaxImageSide || wh[1] > kMaxImageSide) throw UsageError(usage);
  if (uint64_t(wh[0] * wh[1]) > kMaxImagePixels)
    throw UsageError(option + " " + text + " has more than " + std::to_string(kMaxImagePixels) +
                     " pixels (e.g. 16384x8192), the most mjray renders");
  return {int(wh[0]), int(wh[1])};
}

/// --crop X0,Y0,X1,Y1: the pixels [X0, X1) × [Y0, Y1), not empty.
PixelRect parse_crop(const std::string& option, const std::string& text) {
  const std::string side = std::to_string(kMaxImageSide);
  const std::string usage = option + " expects X0,Y0,X1,Y1: the window [X0, X1) x [Y0, Y1) in pixels, 0 <= X0 < X1 <= " +
                            side + " and 0 <= Y0 < Y1 <= " + side + ", got '" + text + "'";
  const auto v = parse_integers(text, ',', 4, usage);
  if (v[0] < 0 || v[1] < 0 || v[0] >= v[2] || v[1] >= v[3] || v[2] > kMaxImageSide || v[3] > kMaxImageSide)
    throw UsageError(usage);
  return {int(v[0]), int(v[1]), int(v[2]), int(v[3])};
}

/// --frames A-B[:STEP] or N: 1-based gr.render calls, A <= B, STEP >= 1.
FrameRange parse_frames(const std::string& option, const std::string& text) {
  const std::string usage = option + " expects A-B or A-B:STEP (1-based gr.render calls, A <= B) or one call N, got '" + text + "'";
  const size_t colon = text.find(':');
  const std::string range = text.substr(0, colon);
  FrameRange frames;
  const auto bounds = parse_integers(range, '-', range.find('-') == std::string::npos ? 1 : 2, usage);
  frames.first = int(std::clamp(bounds.front(), -1LL, 1LL << 30));
  frames.last = int(std::clamp(bounds.back(), -1LL, 1LL << 30));
  if (colon != std::string::npos) frames.step = int(std::clamp(parse_integers(text.substr(colon + 1), ':', 1, usage)[0], -1LL, 1LL << 30));
  if (frames.first < 1 || *frames.last < frames.first || frames.step < 1) throw UsageError(usage);
  return frames;
}

/// -D NAME=VALUE: NAME a Lua identifier that is not a keyword, defined once.
void add_define(SceneLoadOptions& load, const std::string& option, const std::string& text) {
  static const std::set<std::string> keywords = {"and", "break", "do", "else", "elseif", "end", "false", "for",
                                                 "function", "goto", "if", "in", "local", "nil", "not", "or",
                                                 "repeat", "return", "then", "true", "until", "while"};
  const size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                          std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (eq == std::string::npos || !identifier || keywords.count(name))
    throw UsageError(option + " expects NAME=VALUE with NAME a Lua name (letters, digits, _; not a keyword), got '" + text + "'");
  for (const auto& [defined, value] : load.defines)
    if (defined == name)
      throw UsageError(option + " " + text + ": " + name + " is already defined (as " + name + "=" + value + "); define it once");
  load.defines.emplace_back(name, text.substr(eq + 1));
}

/// One of `choices`, or a UsageError listing them ("grid or subdivide").
std::string parse_choice(const std::string& option, const std::string& text, const std::vector<std::string>& choices) {
  if (std::find(choices.begin(), choices.end(), text) != choices.end()) return text;
  std::string listed;
  for (size_t i = 0; i < choices.size(); ++i)
    listed += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  throw UsageError(option + " expects " + listed + ", got '" + text + "'");
}

/// The video formats --video makes, by extension.
bool is_video_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".mp4" || extension == ".webm" || extension == ".gif";
}

/// A numeric IPv4 or IPv6 address (no host names: --listen says exactly which interface).
bool is_ip_address(const std::string& text) {
  unsigned char address[16];
  return inet_pton(AF_INET, text.c_str(), address) == 1 || inet_pton(AF_INET6, text.c_str(), address) == 1;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// --- the table -----------------------------------------------------------------------------

#ifdef MJRAY_HAVE_EMBREE
constexpr const char* kAccelKinds = "bvh (default), grid, none, embree";
#else
constexpr const char* kAccelKinds = "bvh (default), grid, none (embree: not in this build)";
#endif

std::vector<OptionSpec> make_table() {
  constexpr long long kMaxInt = 1 << 30;
  return {
      // What the image is: every one of these is in the resume fingerprint.
      {{"-r"}, "N", "max reflection depth (default 8)",
       [](RunOptions& o, auto& n, auto& v) { o.job.integrator.max_reflection_depth = int(parse_integer(n, v, 0, 1000)); },
       [](const JobOptions& o) { return std::to_string(o.integrator.max_reflection_depth); }},
      {{"-f"}, "N", "max refraction depth (default 8)",
       [](RunOptions& o, auto& n, auto& v) { o.job.integrator.max_refraction_depth = int(parse_integer(n, v, 0, 1000)); },
       [](const JobOptions& o) { return std::to_string(o.integrator.max_refraction_depth); }},
      {{"-s"}, "N", "area-light samples: an N x N jittered grid (default 1)",
       [](RunOptions& o, auto& n, auto& v) { o.job.integrator.area_light_samples = int(parse_integer(n, v, 1, 1024)); },
       [](const JobOptions& o) { return std::to_string(o.integrator.area_light_samples); }},
      {{"-a"}, "N", "adaptive anti-aliasing with N x N samples in bad pixels (default 0: off)",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.antialias_samples = int(parse_integer(n, v, 0, 64)); },
       [](const JobOptions& o) { return std::to_string(o.render.antialias_samples); }},
      {{"--aa-threshold"}, "T",
       "colour difference from a neighbour that makes a pixel bad, or between a square's corners that splits it "
       "(default 0.1)",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.antialias_threshold = float(parse_real(n, v, 0, 1, "a number in (0, 1]")); },
       [](const JobOptions& o) { return number_text(o.render.antialias_threshold); }},
      {{"--aa-method"}, "grid|subdivide",
       "how -a works: grid, N x N jittered samples in each bad pixel and its neighbours (default); subdivide, every "
       "pixel sampled at its corners, shared with its neighbours, and squares whose corners differ by more than the "
       "threshold split in four, down to cells of 1/N pixel (as POV-Ray's +AM2); about 1.6x faster for the same "
       "image error on glass",
       [](RunOptions& o, auto& n, auto& v) {
         o.job.render.antialias_method =
             parse_choice(n, v, {"grid", "subdivide"}) == "grid" ? AntialiasMethod::kGrid : AntialiasMethod::kSubdivide;
       },
       [](const JobOptions& o) { return std::string(o.render.antialias_method == AntialiasMethod::kGrid ? "grid" : "subdivide"); }},
      {{"--spp"}, "N",
       "N stratified samples in every pixel (default 1: the pixel centre); with -a, a bad pixel gets N x N cells of N "
       "samples",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.samples_per_pixel = int(parse_integer(n, v, 1, 4096)); },
       [](const JobOptions& o) { return std::to_string(o.render.samples_per_pixel); }},
      {{"--noise-threshold"}, "T",
       "render until clean: after a first pass of at least 16 samples in every pixel, passes double the samples of "
       "every pixel whose estimated error, relative to the square root of its brightness, is still above T (and of "
       "its neighbours), up to --max-spp; 0.01 is clean, 0.05 a draft (default 0: off; not with -a)",
       [](RunOptions& o, auto& n, auto& v) {
         o.job.render.noise_threshold = v == "0" ? 0.f : float(parse_real(n, v, 0, 1, "a number in (0, 1], or 0 for off"));
       },
       [](const JobOptions& o) { return number_text(o.render.noise_threshold); }},
      {{"--max-spp"}, "N", "the most samples --noise-threshold gives a pixel (default 4096)",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.max_samples_per_pixel = int(parse_integer(n, v, 1, 1 << 20)); },
       [](const JobOptions& o) { return std::to_string(o.render.max_samples_per_pixel); }},
      {{"--seed"}, "N", "seed of all random sampling, and of the script's math.random (default 0)",
       [](RunOptions& o, auto& n, auto& v) {
         o.job.render.seed = uint64_t(parse_integer(n, v, 0, kMaxInt * kMaxInt));
         o.load.random_seed = o.job.render.seed;
       },
       [](const JobOptions& o) { return std::to_string(o.render.seed); }},
      {{"--tile-size"}, "N",
       "pixels on a side of a tile, the piece of image a thread renders at a time (default 16); any size gives the "
       "same image, but a resume needs the size it began with",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.tile_size = int(parse_integer(n, v, 1, 4096)); },
       [](const JobOptions& o) { return std::to_string(o.render.tile_size); }},
      {{"--caustics"}, "N", "photon-mapped caustics from N photons (e.g. 1e6; default 0: off)",
       [](RunOptions& o, auto& n, auto& v) { o.job.photons.caustic_photons = parse_photon_count(n, v); },
       [](const JobOptions& o) { return std::to_string(o.photons.caustic_photons); }},
      {{"--caustic-passes"}, "K",
       "progressive caustics: K passes of --caustics N fresh photons each, searched over a shrinking radius; a "
       "pixel's camera samples read the passes in turn, so that its caustics converge as it is sampled (default 1)",
       [](RunOptions& o, auto& n, auto& v) { o.job.photons.caustic_passes = int(parse_integer(n, v, 1, 4096)); },
       [](const JobOptions& o) { return std::to_string(o.photons.caustic_passes); }},
      {{"--gi"}, "N", "global illumination: N photons and final gathering (default 0: off)",
       [](RunOptions& o, auto& n, auto& v) { o.job.photons.global_photons = parse_photon_count(n, v); },
       [](const JobOptions& o) { return std::to_string(o.photons.global_photons); }},
      {{"--gather-rays"}, "N",
       "with --gi, final-gather rays per camera sample at a surface (a square grid; default 64); with "
       "--noise-threshold, 4 and more samples where the gathers disagree spend the time better",
       [](RunOptions& o, auto& n, auto& v) { o.job.photons.gather_rays = int(parse_integer(n, v, 1, 4096)); },
       [](const JobOptions& o) { return std::to_string(o.photons.gather_rays); }},
      {{"--aperture"}, "R", "thin-lens depth of field with lens radius R (overrides gr.lens; 0 = pinhole)",
       [](RunOptions& o, auto& n, auto& v) { o.job.view.aperture_radius = float(parse_at_least_zero(n, v, "a lens radius of at least 0")); },
       nullptr},  // in the fingerprint's "lens" line, with gr.lens's
      {{"--focus-distance"}, "D", "distance along the view direction that is in focus (overrides gr.lens)",
       [](RunOptions& o, auto& n, auto& v) { o.job.view.focus_distance = float(parse_real(n, v, 0, 1e30, "a distance above 0")); },
       nullptr},  // in the "lens" line
      {{"--size"}, "WxH", "render at W x H pixels with the same camera (the vertical field of view is kept)",
       [](RunOptions& o, auto& n, auto& v) { std::tie(o.job.view.width, o.job.view.height) = parse_size(n, v); },
       nullptr},  // in the "size" line, with gr.render's
      {{"--crop"}, "X0,Y0,X1,Y1", "render and write only the pixels [X0, X1) x [Y0, Y1) of the image",
       [](RunOptions& o, auto& n, auto& v) { o.job.render.crop = parse_crop(n, v); },
       [](const JobOptions& o) {
         const auto& c = o.render.crop;
         return c ? std::to_string(c->x0) + "," + std::to_string(c->y0) + "," + std::to_string(c->x1) + "," + std::to_string(c->y1)
                  : std::string("whole image");
       }},
      {{"--gamma"}, "linear|srgb",
       "encoding of 8-bit output (default linear, as CS 488); srgb also decodes 8-bit image textures from sRGB",
       [](RunOptions& o, auto& n, auto& v) {
         const bool srgb = parse_choice(n, v, {"linear", "srgb"}) == "srgb";
         o.job.outputs.encoding.gamma = srgb ? OutputGamma::kSrgb : OutputGamma::kLinear;
         o.load.srgb_textures = srgb;
       },
       [](const JobOptions& o) { return std::string(o.outputs.encoding.gamma == OutputGamma::kSrgb ? "srgb" : "linear"); }},
      {{"--bit-depth"}, "8|16", "bits per channel of PNG output (default 8)",
       [](RunOptions& o, auto& n, auto& v) { o.job.outputs.encoding.bit_depth = parse_choice(n, v, {"8", "16"}) == "8" ? 8 : 16; },
       [](const JobOptions& o) { return std::to_string(o.outputs.encoding.bit_depth); }},
      {{"--jpeg-quality"}, "N", "quality of .jpg output, 1 to 100 (default 90)",
       [](RunOptions& o, auto& n, auto& v) { o.job.outputs.encoding.jpeg_quality = int(parse_integer(n, v, 1, 100)); },
       [](const JobOptions& o) { return std::to_string(o.outputs.encoding.jpeg_quality); }},

      // How it is computed: the same image whatever these say.
      {{"-g"}, "N", "uniform grid with N x N x N voxels; -g 0 = no acceleration",
       [](RunOptions& o, auto& n, auto& v) { o.accel_request.grid_size = int(parse_integer(n, v, 0, 4096)); }},
      {{"-o"}, "", "uniform grid of the \"optimal\" size 3*cbrt(primitives); overrides -g",
       [](RunOptions& o, auto&, auto&) { o.accel_request.optimal_grid = true; }},
      {{"--accel"}, "KIND", std::string("acceleration structure: ") + kAccelKinds,
       [](RunOptions& o, auto& n, auto& v) { o.accel_request.named = parse_choice(n, v, {"bvh", "grid", "none", "embree"}); }},
      {{"-j", "--threads"}, "N", "worker threads (default: all cores)",
       [](RunOptions& o, auto& n, auto& v) {
         const int threads = int(parse_integer(n, v, 1, 4096));
         o.job.accel.threads = o.job.render.threads = threads;
         o.job.outputs.encoding.threads = resolve_thread_count(threads);
       }},

      // Where images go, and which.
      {{"--output"}, "FILE",
       "write the (single) image to FILE (its folder is created); the extension picks the format: .png, .ppm, .jpg, "
       ".exr (linear half float)",
       [](RunOptions& o, auto&, auto& v) { o.job.outputs.output = v; }},
      {{"--outdir"}, "DIR", "write every image into DIR (created), under the file name gr.render gives",
       [](RunOptions& o, auto&, auto& v) { o.job.outputs.outdir = v; }},
      {{"--frames"}, "A-B[:STEP]", "render only these gr.render calls (1-based, in script order), e.g. 3-5, 1-96:4, 7",
       [](RunOptions& o, auto& n, auto& v) { o.job.frames = parse_frames(n, v); }},
      {{"--video"}, "FILE", "encode the rendered images in order into FILE (.mp4, .webm or .gif) with ffmpeg",
       [](RunOptions& o, auto& n, auto& v) {
         if (!is_video_extension(v)) throw UsageError(n + " expects a file ending in .mp4, .webm or .gif, got '" + v + "'");
         o.report.video = v;
       }},
      {{"--fps"}, "N", "frames per second of --video (default 24)",
       [](RunOptions& o, auto& n, auto& v) { o.report.fps = int(parse_integer(n, v, 1, 1000)); }},

      // The script.
      {{"-D", "--define"}, "NAME=VALUE",
       "set the Lua global NAME before the script runs (a number when VALUE reads as one, else a string), e.g. "
       "-D frame=7",
       [](RunOptions& o, auto& n, auto& v) { add_define(o.load, n, v); }},
      {{"--transform-order"}, "pre|post|auto",
       "how node transforms compose (default auto: post when the first gr.render draws a table-form gr.mesh or a "
       "gr.extendedmesh, else pre)",
       [](RunOptions& o, auto& n, auto& v) {
         const std::string order = parse_choice(n, v, {"pre", "post", "auto"});
         o.load.transform_order = order == "pre" ? TransformOrder::kPre : order == "post" ? TransformOrder::kPost : TransformOrder::kAuto;
       }},
      {{"--unsafe-lua"}, "",
       "give the script the full Lua standard library, every file to read, and images anywhere",
       [](RunOptions& o, auto&, auto&) {
         o.load.unsafe_lua = true;
         o.job.outputs.confine_script_outputs = false;
       }},
      {{"--allow-read"}, "DIR",
       "let the script read files in DIR and its subfolders too (besides its own folder's tree and the working "
       "directory's); may be given several times",
       [](RunOptions& o, auto& n, auto& v) {
         std::error_code ec;
         if (!std::filesystem::is_directory(v, ec)) throw UsageError(n + " expects a folder, and '" + v + "' is not one");
         o.load.allowed_read_folders.push_back(std::filesystem::absolute(v));
       }},
      {{"--lua-memory"}, "SIZE",
       "most memory the script may use, its Lua state and what its gr.* calls keep, e.g. 512MiB (default 4GiB; 0 = no "
       "limit)",
       [](RunOptions& o, auto& n, auto& v) { o.load.lua_memory_bytes = parse_bytes(n, v); }},
      {{"--scene-timeout"}, "S", "stop a script still running after S seconds (default 600; 0 = no limit)",
       [](RunOptions& o, auto& n, auto& v) {
         o.load.timeout_seconds = v == "0" ? 0 : parse_real(n, v, 0, 1e6, "a number of seconds from 0 (no limit) to 1000000");
       }},

      // What the run says and does.
      {{"--stats"}, "", "print the statistics of each image (time, rays, memory)",
       [](RunOptions& o, auto&, auto&) { o.report.print_stats = true; }},
      {{"--stats-json"}, "FILE", "write the statistics as JSON",
       [](RunOptions& o, auto&, auto& v) { o.report.stats_json = v; }},
      {{"--time-limit"}, "S",
       "stop after S seconds and write what is done: the images rendered, and the one under way as far as it got, "
       "with its state, so that --resume goes on refining it (the only option whose images depend on the machine)",
       [](RunOptions& o, auto& n, auto& v) {
         o.report.time_limit_seconds = parse_real(n, v, 0, 1e9, "a number of seconds above 0");
       }},
      {{"--quiet"}, "", "only warnings and errors (and the statistics that --stats asks for)",
       [](RunOptions& o, auto&, auto&) { o.report.quiet = true; }},
      {{"--resume"}, "",
       "finish an interrupted render or animation: keep complete images, resume the interrupted one, render the rest",
       [](RunOptions& o, auto&, auto&) { o.report.resume = true; }},
      {{"--watch"}, "",
       "live preview: serve a page showing the render as it refines, and render again whenever the script or a file "
       "it reads changes (Ctrl-C ends it)",
       [](RunOptions& o, auto&, auto&) { o.report.watch = true; }},
      {{"--port"}, "N",
       "the page's port (default " + std::to_string(kDefaultWatchPort) + ", or the next free one; 0 = any free port)",
       [](RunOptions& o, auto& n, auto& v) { o.report.port = int(parse_integer(n, v, 0, 65535)); }},
      {{"--listen"}, "ADDR",
       "serve on this address instead of 127.0.0.1 (anyone who can reach it can see the renders)",
       [](RunOptions& o, auto& n, auto& v) {
         if (!is_ip_address(v)) throw UsageError(n + " expects an IP address such as 127.0.0.1, 0.0.0.0 or ::1, got '" + v + "'");
         o.report.listen = v;
       }},
  };
}

}  // namespace

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> table = make_table();
  return table;
}

std::vector<std::string> resolve_options(RunOptions& options) {
  const AcceleratorRequest& r = options.accel_request;
  AcceleratorOptions& accel = options.job.accel;
  std::vector<std::string> warnings;
  if (options.report.fps != 24 && !options.report.video) warnings.push_back("--fps has no effect without --video");
  const RenderSettings& render = options.job.render;
  if (render.targets_noise() && render.antialias_samples > 0)
    throw UsageError("--noise-threshold and -a cannot be used together: -a is the report's anti-aliasing of bad pixels, "
                     "--noise-threshold samples every pixel until it is clean; choose one");
  if (options.report.watch && options.report.time_limit_seconds > 0)
    throw UsageError("--time-limit and --watch cannot be used together: the live preview renders each change until it is "
                     "done or the scene changes again");
  if (!render.targets_noise() && render.max_samples_per_pixel != RenderSettings{}.max_samples_per_pixel)
    warnings.push_back("--max-spp has no effect without --noise-threshold");
  // Compute the accelerator: --accel wins, then -o, then -g.
  if (r.optimal_grid) {
    accel.kind = "grid";
    accel.grid_size = 0;
  } else if (r.grid_size) {
    accel.kind = *r.grid_size == 0 ? "none" : "grid";
    accel.grid_size = *r.grid_size;
  }
  if (!r.named.empty()) accel.kind = r.named;
  if (r.named.empty() || r.named == "grid") {
    if (r.optimal_grid && r.grid_size) warnings.push_back("-g has no effect with -o (-o chooses the grid's size itself)");
    return warnings;
  }
  if (r.grid_size) warnings.push_back("-g has no effect with --accel " + r.named + " (it sizes the grid of --accel grid)");
  if (r.optimal_grid) warnings.push_back("-o has no effect with --accel " + r.named + " (it sizes the grid of --accel grid)");
  return warnings;
}

}  // namespace mjray
