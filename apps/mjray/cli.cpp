#include "cli.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include <arpa/inet.h>

#include "mjray/core/image.h"
#include "mjray/core/parallel_for.h"

namespace mjray {

namespace {

long long parse_integer(const std::string& option, const std::string& text, long long lo, long long hi) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
    throw UsageError(option + " expects a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
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

/// A number in (lo, hi], for --aa-threshold and --scene-timeout.
double parse_real(const std::string& option, const std::string& text, double lo, double hi, const std::string& expected) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > lo && value <= hi))
    throw UsageError(option + " expects " + expected + ", got '" + text + "'");
  return value;
}

// --- camera, image and animation values ----------------------------------------------------

/// A number of at least 0 (--aperture).
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
    throw UsageError(option + " " + text + " has more than 2^27 pixels (e.g. 16384x8192), the most mjray renders");
  return {int(wh[0]), int(wh[1])};
}

/// --crop X0,Y0,X1,Y1: the pixels [X0, X1) × [Y0, Y1), not empty.
PixelRect parse_crop(const std::string& option, const std::string& text) {
  const std::string usage = option + " expects X0,Y0,X1,Y1: the window [X0, X1) x [Y0, Y1) in pixels, "
                            "0 <= X0 < X1 <= 65536 and 0 <= Y0 < Y1 <= 65536, got '" + text + "'";
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
  const auto bounds = range.find('-') == std::string::npos ? parse_integers(range, '-', 1, usage) : parse_integers(range, '-', 2, usage);
  frames.first = int(std::clamp(bounds.front(), -1LL, 1LL << 30));
  frames.last = int(std::clamp(bounds.back(), -1LL, 1LL << 30));
  if (colon != std::string::npos) frames.step = int(std::clamp(parse_integers(text.substr(colon + 1), ':', 1, usage)[0], -1LL, 1LL << 30));
  if (frames.first < 1 || *frames.last < frames.first || frames.step < 1) throw UsageError(usage);
  return frames;
}

/// -D NAME=VALUE: NAME a Lua identifier that is not a keyword.
std::pair<std::string, std::string> parse_define(const std::string& option, const std::string& text) {
  static const std::set<std::string> keywords = {"and", "break", "do", "else", "elseif", "end", "false", "for",
                                                 "function", "goto", "if", "in", "local", "nil", "not", "or",
                                                 "repeat", "return", "then", "true", "until", "while"};
  const size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                          std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (eq == std::string::npos || !identifier || keywords.count(name))
    throw UsageError(option + " expects NAME=VALUE with NAME a Lua name (letters, digits, _; not a keyword), got '" + text + "'");
  return {name, text.substr(eq + 1)};
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

#ifdef MJRAY_HAVE_EMBREE
constexpr const char* kAccelKinds = "bvh (default), grid, none, embree";
#else
constexpr const char* kAccelKinds = "bvh (default), grid, none (embree: not in this build)";
#endif

using ValueHandler = std::function<void(const std::string& option, const std::string& value)>;
using FlagHandler = std::function<void()>;

/// The options of the command line, by every name they have, and the argument walk.
class Parser {
 public:
  explicit Parser(CommandLine& cl);
  void parse(const std::vector<std::string>& args);

 private:
  void long_option(const std::string& arg, const std::vector<std::string>& args, size_t& i);
  void short_options(const std::string& arg, const std::vector<std::string>& args, size_t& i);
  /// --spp, the lens, --size, --crop, --frames, -D, --video, --fps and the encodings.
  void add_camera_and_animation_options(CommandLine& cl);

  CommandLine& cl_;
  std::map<std::string, ValueHandler> with_value_;
  std::map<std::string, FlagHandler> flags_;
  std::vector<std::string> positional_;
  bool o_ends_argument_ = false;                   // the last argument ended with the flag -o
  size_t positional_after_o_ = std::string::npos;  // in positional_: the argument right after -o
};

Parser::Parser(CommandLine& cl) : cl_(cl) {
  constexpr long long kMaxInt = 1 << 30;
  const ValueHandler threads = [&](auto& o, auto& v) { cl.threads = int(parse_integer(o, v, 1, 4096)); };
  with_value_ = {
      {"-r", [&](auto& o, auto& v) { cl.max_reflection_depth = int(parse_integer(o, v, 0, 1000)); }},
      {"-f", [&](auto& o, auto& v) { cl.max_refraction_depth = int(parse_integer(o, v, 0, 1000)); }},
      {"-g", [&](auto& o, auto& v) { cl.grid_size = int(parse_integer(o, v, 0, 4096)); }},
      {"-s", [&](auto& o, auto& v) { cl.area_light_samples = int(parse_integer(o, v, 1, 1024)); }},
      {"-a", [&](auto& o, auto& v) { cl.antialias_samples = int(parse_integer(o, v, 0, 64)); }},
      {"-j", threads},
      {"--threads", threads},
      {"--tile-size", [&](auto& o, auto& v) { cl.tile_size = int(parse_integer(o, v, 1, 4096)); }},
      {"--seed", [&](auto& o, auto& v) {
         cl.seed = uint64_t(parse_integer(o, v, 0, kMaxInt * kMaxInt));
         cl.load.random_seed = cl.seed;
       }},
      {"--aa-threshold", [&](auto& o, auto& v) { cl.antialias_threshold = float(parse_real(o, v, 0, 1, "a number in (0, 1]")); }},
      {"--lua-memory", [&](auto& o, auto& v) { cl.load.lua_memory_bytes = parse_bytes(o, v); }},
      {"--scene-timeout", [&](auto& o, auto& v) {
         cl.load.timeout_seconds = v == "0" ? 0 : parse_real(o, v, 0, 1e6, "a number of seconds from 0 (no limit) to 1000000");
       }},
      {"--caustics", [&](auto& o, auto& v) { cl.caustic_photons = parse_photon_count(o, v); }},
      {"--gi", [&](auto& o, auto& v) { cl.global_photons = parse_photon_count(o, v); }},
      {"--allow-read", [&](auto& o, auto& v) {
         std::error_code ec;
         if (!std::filesystem::is_directory(v, ec)) throw UsageError(o + " expects a folder, and '" + v + "' is not one");
         cl.load.allowed_read_folders.push_back(std::filesystem::absolute(v));
       }},
      {"--output", [&](auto&, auto& v) { cl.output = v; }},
      {"--outdir", [&](auto&, auto& v) { cl.outdir = v; }},
      {"--stats-json", [&](auto&, auto& v) { cl.stats_json = v; }},
      {"--port", [&](auto& o, auto& v) { cl.port = int(parse_integer(o, v, 0, 65535)); }},
      {"--listen", [&](auto& o, auto& v) {
         if (!is_ip_address(v)) throw UsageError(o + " expects an IP address such as 127.0.0.1, 0.0.0.0 or ::1, got '" + v + "'");
         cl.listen = v;
       }},
      {"--accel", [&](auto& o, auto& v) {
         if (v != "bvh" && v != "grid" && v != "none" && v != "embree")
           throw UsageError(o + " expects bvh, grid, none or embree, got '" + v + "'");
         cl.accel = v;
       }},
      {"--aa-method", [&](auto& o, auto& v) {
         if (v == "grid") cl.antialias_method = AntialiasMethod::kGrid;
         else if (v == "subdivide") cl.antialias_method = AntialiasMethod::kSubdivide;
         else throw UsageError(o + " expects grid or subdivide, got '" + v + "'");
       }},
      {"--gamma", [&](auto& o, auto& v) {
         if (v != "linear" && v != "srgb") throw UsageError(o + " expects linear or srgb, got '" + v + "'");
         cl.srgb = v == "srgb";
         cl.load.srgb_textures = cl.srgb;
       }},
      {"--transform-order", [&](auto& o, auto& v) {
         if (v == "pre") cl.load.transform_order = TransformOrder::kPre;
         else if (v == "post") cl.load.transform_order = TransformOrder::kPost;
         else if (v == "auto") cl.load.transform_order = TransformOrder::kAuto;
         else throw UsageError(o + " expects pre, post or auto, got '" + v + "'");
       }},
  };
  add_camera_and_animation_options(cl);
  flags_ = {
      {"-o", [&] { cl.optimal_grid = true; }},
      {"--stats", [&] { cl.print_stats = true; }},
      {"--quiet", [&] { cl.quiet = true; }},
      {"--resume", [&] { cl.resume = true; }},
      {"--watch", [&] { cl.watch = true; }},
      {"--unsafe-lua", [&] { cl.load.unsafe_lua = true; }},
      {"-h", [&] { cl.show_help = true; }},
      {"--help", [&] { cl.show_help = true; }},
      {"--version", [&] { cl.show_version = true; }},
  };
}

void Parser::add_camera_and_animation_options(CommandLine& cl) {
  const ValueHandler define = [&](auto& o, auto& v) {
    auto definition = parse_define(o, v);
    for (const auto& [name, value] : cl.load.defines)
      if (name == definition.first)
        throw UsageError(o + " " + v + ": " + name + " is already defined (as " + name + "=" + value + "); define it once");
    cl.load.defines.push_back(std::move(definition));
  };
  with_value_.insert({
      {"--spp", [&](auto& o, auto& v) { cl.samples_per_pixel = int(parse_integer(o, v, 1, 4096)); }},
      {"--aperture", [&](auto& o, auto& v) { cl.aperture_radius = float(parse_at_least_zero(o, v, "a lens radius of at least 0")); }},
      {"--focus-distance", [&](auto& o, auto& v) {
         cl.focus_distance = float(parse_real(o, v, 0, 1e30, "a distance above 0"));
       }},
      {"--size", [&](auto& o, auto& v) { std::tie(cl.width, cl.height) = parse_size(o, v); }},
      {"--crop", [&](auto& o, auto& v) { cl.crop = parse_crop(o, v); }},
      {"--frames", [&](auto& o, auto& v) { cl.frames = parse_frames(o, v); }},
      {"-D", define},
      {"--define", define},
      {"--video", [&](auto& o, auto& v) {
         if (!is_video_extension(v)) throw UsageError(o + " expects a file ending in .mp4, .webm or .gif, got '" + v + "'");
         cl.video = v;
       }},
      {"--fps", [&](auto& o, auto& v) { cl.fps = int(parse_integer(o, v, 1, 1000)); }},
      {"--bit-depth", [&](auto& o, auto& v) {
         if (v != "8" && v != "16") throw UsageError(o + " expects 8 or 16, got '" + v + "'");
         cl.bit_depth = v == "8" ? 8 : 16;
       }},
      {"--jpeg-quality", [&](auto& o, auto& v) { cl.jpeg_quality = int(parse_integer(o, v, 1, 100)); }},
  });
}

void Parser::long_option(const std::string& arg, const std::vector<std::string>& args, size_t& i) {
  const size_t eq = arg.find('=');
  const std::string name = arg.substr(0, eq);
  if (const auto flag = flags_.find(name); flag != flags_.end()) {
    if (eq != std::string::npos) throw UsageError(name + " takes no value, got '" + arg + "'");
    flag->second();
    return;
  }
  const auto option = with_value_.find(name);
  if (option == with_value_.end()) throw UsageError("unknown option '" + name + "'");
  if (eq != std::string::npos) return option->second(name, arg.substr(eq + 1));
  if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
  option->second(name, args[++i]);
}

// getopt style: "-r4", "-r 4", and flags grouped with at most one valued option last: "-og 5".
void Parser::short_options(const std::string& arg, const std::vector<std::string>& args, size_t& i) {
  for (size_t k = 1; k < arg.size(); ++k) {
    const std::string name = std::string("-") + arg[k];
    if (const auto flag = flags_.find(name); flag != flags_.end()) {
      flag->second();
      o_ends_argument_ = name == "-o" && k + 1 == arg.size();
      continue;
    }
    const auto option = with_value_.find(name);
    if (option == with_value_.end())
      throw UsageError(k == 1 ? "unknown option '" + arg + "'" : "unknown option '" + name + "' in '" + arg + "'");
    if (k + 1 < arg.size()) return option->second(name, arg.substr(k + 1));
    if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
    return option->second(name, args[++i]);
  }
}

void Parser::parse(const std::vector<std::string>& args) {
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool follows_o = std::exchange(o_ends_argument_, false);
    if (options_ended || arg.size() < 2 || arg[0] != '-') {
      if (follows_o) positional_after_o_ = positional_.size();
      positional_.push_back(arg);
    } else if (arg == "--") options_ended = true;
    else if (arg[1] == '-') long_option(arg, args, i);
    else short_options(arg, args, i);
  }
  if (cl_.show_help || cl_.show_version) return;
  // "-o out.png scene.lua": the original's -o is the optimal grid, not an output file.
  if (positional_.size() == 2 && positional_after_o_ < 2 && !positional_[positional_after_o_].ends_with(".lua"))
    throw UsageError("-o takes no value: did you mean --output " + positional_[positional_after_o_] +
                     "? (-o asks for the uniform grid of optimal size)");
  if (positional_.size() != 1)
    throw UsageError(positional_.empty() ? "no scene file given" : "give exactly one scene file");
  cl_.scene = positional_[0];
  if (cl_.output && cl_.outdir) throw UsageError("--output and --outdir cannot be used together");
  if (!cl_.watch && (cl_.port || cl_.listen)) throw UsageError(std::string(cl_.port ? "--port" : "--listen") + " needs --watch");
  if (cl_.watch && cl_.resume) throw UsageError("--watch and --resume cannot be used together (finish the render with --resume first)");
  if (cl_.watch && cl_.video) throw UsageError("--watch and --video cannot be used together (make the video without --watch)");
  if (cl_.watch && cl_.crop) throw UsageError("--watch and --crop cannot be used together (the preview shows whole frames)");
}

/// Options that change nothing with the others given, each named once.
std::vector<std::string> ignored_options(const CommandLine& cl) {
  std::vector<std::string> warnings;
  if (cl.fps != 24 && !cl.video) warnings.push_back("--fps has no effect without --video");
  if (cl.accel.empty() || cl.accel == "grid") {
    if (cl.optimal_grid && cl.grid_size) warnings.push_back("-g has no effect with -o (-o chooses the grid's size itself)");
    return warnings;
  }
  if (cl.grid_size) warnings.push_back("-g has no effect with --accel " + cl.accel + " (it sizes the grid of --accel grid)");
  if (cl.optimal_grid) warnings.push_back("-o has no effect with --accel " + cl.accel + " (it sizes the grid of --accel grid)");
  return warnings;
}

}  // namespace

std::string usage_text() {
  return std::string(R"(usage: mjray [options] scene.lua

Renders the images a Lua scene script asks for with gr.render(...). Short options take their
value attached or apart and group as with getopt: -s4, -s 4, -og 5.

options:
  -r N                 max reflection depth (default 8)
  -f N                 max refraction depth (default 8)
  -g N                 uniform grid with N x N x N voxels; -g 0 = no acceleration
  -o                   uniform grid of the "optimal" size 3*cbrt(primitives); overrides -g
  -s N                 area-light samples: an N x N jittered grid (default 1)
  -a N                 adaptive anti-aliasing with N x N samples in bad pixels (default 0: off)
  --aa-threshold T     colour difference from a neighbour that makes a pixel bad, or between a
                       square's corners that splits it (default 0.1)
  --aa-method grid|subdivide
                       how -a works: grid, N x N jittered samples in each bad pixel and its
                       neighbours (default); subdivide, every pixel sampled at its corners,
                       shared with its neighbours, and squares whose corners differ by more
                       than the threshold split in four, down to cells of 1/N pixel (as
                       POV-Ray's +AM2); about 1.6x faster for the same image error on glass
  --accel KIND         acceleration structure: )") + kAccelKinds + R"(
  -j, --threads N      worker threads (default: all cores)
  --tile-size N        pixels on a side of a tile, the piece of image a thread renders at a
                       time (default 16); any size gives the same image
  --output FILE        write the (single) image to FILE (its folder is created); the extension
                       picks the format: .png, .ppm, .jpg, .exr (linear half float)
  --outdir DIR         write every image into DIR (created), under the file name gr.render gives
  --stats              print the statistics of each image (time, rays, memory)
  --stats-json FILE    write the statistics as JSON
  --seed N             seed of all random sampling (default 0)
  --gamma linear|srgb  encoding of 8-bit output (default linear, as CS 488); srgb also decodes
                       8-bit image textures from sRGB
  --spp N              N stratified samples in every pixel (default 1: the pixel centre); with
                       -a, a bad pixel gets N x N cells of N samples
  --aperture R         thin-lens depth of field with lens radius R (overrides gr.lens; 0 = pinhole)
  --focus-distance D   distance along the view direction that is in focus (overrides gr.lens)
  --size WxH           render at W x H pixels with the same camera (the vertical field of view
                       is kept)
  --crop X0,Y0,X1,Y1   render and write only the pixels [X0, X1) x [Y0, Y1) of the image
  --frames A-B[:STEP]  render only these gr.render calls (1-based, in script order), e.g. 3-5,
                       1-96:4, 7
  -D, --define NAME=VALUE
                       set the Lua global NAME before the script runs (a number when VALUE reads
                       as one, else a string), e.g. -D frame=7
  --video FILE         encode the rendered images in order into FILE (.mp4, .webm or .gif) with
                       ffmpeg
  --fps N              frames per second of --video (default 24)
  --bit-depth 8|16     bits per channel of PNG output (default 8)
  --jpeg-quality N     quality of .jpg output, 1 to 100 (default 90)
  --transform-order pre|post|auto
                       how node transforms compose (default auto: post when the first
                       gr.render draws a table-form gr.mesh or a gr.extendedmesh, else pre)
  --caustics N         photon-mapped caustics from N photons (e.g. 1e6; default 0: off)
  --gi N               global illumination: N photons and final gathering (default 0: off)
  --quiet              only warnings and errors (and the statistics that --stats asks for)
  --resume             finish an interrupted render or animation: keep complete images,
                       resume the interrupted one, render the rest
  --unsafe-lua         give the script the full Lua standard library and let it write images
                       outside the scene's folder and the working directory
  --allow-read DIR     let the script read files in DIR and its subfolders too (besides its own
                       folder's tree and the working directory's); may be given several times
  --lua-memory SIZE    most memory the script's Lua state may use, e.g. 512MiB (default 4GiB;
                       0 = no limit)
  --scene-timeout S    stop a script still running after S seconds (default 600; 0 = no limit)
  --watch              live preview: serve a page showing the render as it refines, and render
                       again whenever the script or a file it reads changes (Ctrl-C ends it)
  --port N             the page's port (default )" + std::to_string(kDefaultWatchPort) + R"(, or the next free one; 0 = any free port)
  --listen ADDR        serve on this address instead of 127.0.0.1 (anyone who can reach it can
                       see the renders)
  -h, --help           this text
  --version            the version

exit codes: 0 success, 1 scene or render error, 2 bad command line, 130 interrupted
)";
}

JobOptions job_options(const CommandLine& cl) {
  JobOptions o;
  o.accel.threads = cl.threads;
  if (cl.optimal_grid) {
    o.accel.kind = "grid";
    o.accel.grid_size = 0;
  } else if (cl.grid_size) {
    o.accel.kind = *cl.grid_size == 0 ? "none" : "grid";
    o.accel.grid_size = *cl.grid_size;
  }
  if (!cl.accel.empty()) o.accel.kind = cl.accel;
  o.integrator = {cl.max_reflection_depth, cl.max_refraction_depth, cl.area_light_samples};
  o.render.threads = cl.threads;
  if (cl.tile_size) o.render.tile_size = *cl.tile_size;
  o.render.seed = cl.seed;
  o.render.antialias_samples = cl.antialias_samples;
  o.render.antialias_threshold = cl.antialias_threshold;
  o.render.antialias_method = cl.antialias_method;
  o.photons.caustic_photons = cl.caustic_photons;
  o.photons.global_photons = cl.global_photons;
  o.outputs.output = cl.output;
  o.outputs.outdir = cl.outdir;
  o.outputs.confine_script_outputs = !cl.load.unsafe_lua;
  o.outputs.encoding.gamma = cl.srgb ? OutputGamma::kSrgb : OutputGamma::kLinear;
  o.render.samples_per_pixel = cl.samples_per_pixel;
  o.render.crop = cl.crop;
  o.view = {cl.aperture_radius, cl.focus_distance, cl.width, cl.height};
  o.frames = cl.frames;
  o.outputs.encoding.bit_depth = cl.bit_depth;
  o.outputs.encoding.jpeg_quality = cl.jpeg_quality;
  o.outputs.encoding.threads = resolve_thread_count(cl.threads);
  return o;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  Parser(cl).parse(args);
  cl.warnings = ignored_options(cl);
  return cl;
}

}  // namespace mjray
