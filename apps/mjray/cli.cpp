#include "cli.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <functional>
#include <map>

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

}  // namespace

std::string usage_text() {
  return R"(usage: mjray [options] scene.lua

Renders the images a Lua scene script asks for with gr.render(...).

options:
  -r N                 max reflection depth (default 8)
  -f N                 max refraction depth (default 8)
  -g N                 uniform grid with N x N x N voxels; -g 0 = no acceleration
  -o                   uniform grid of the "optimal" size 3*cbrt(primitives); overrides -g
  -s N                 area-light samples: an N x N jittered grid (default 1)
  -a N                 adaptive anti-aliasing with N x N samples in bad pixels (default 0: off)
  --aa-threshold T     colour difference from a neighbour that makes a pixel bad (default 0.1)
  --accel KIND         acceleration structure: bvh (default), grid, none
  -j, --threads N      worker threads (default: all cores)
  --output FILE        write the (single) image to FILE
  --outdir DIR         write every image into DIR
  --stats              print the statistics
  --stats-json FILE    write the statistics as JSON
  --seed N             seed of all random sampling (default 0)
  --gamma linear|srgb  encoding of 8-bit output (default linear, as CS 488)
  --transform-order pre|post|auto
                       how node transforms compose (default auto: post for scripts that
                       build table-form meshes, as the old course skeleton, else pre)
  --caustics N         photon-mapped caustics from N photons (e.g. 1e6; default 0: off)
  --gi N               global illumination: N photons and final gathering (default 0: off)
  --quiet              no progress output
  --resume             continue an interrupted render
  --unsafe-lua         give the script the full Lua standard library
  --lua-memory SIZE    most memory the script's Lua state may use, e.g. 512MiB (default 4GiB;
                       0 = no limit)
  --scene-timeout S    stop a script still running after S seconds (default: no limit)
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
  o.render.seed = cl.seed;
  o.render.antialias_samples = cl.antialias_samples;
  o.render.antialias_threshold = cl.antialias_threshold;
  o.photons.caustic_photons = cl.caustic_photons;
  o.photons.global_photons = cl.global_photons;
  o.outputs.output = cl.output;
  o.outputs.outdir = cl.outdir;
  o.outputs.encoding.gamma = cl.srgb ? OutputGamma::kSrgb : OutputGamma::kLinear;
  return o;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  constexpr long long kMaxInt = 1 << 30;
  // Options that take a value, by every name they have.
  std::map<std::string, std::function<void(const std::string&, const std::string&)>> with_value = {
      {"-r", [&](auto& o, auto& v) { cl.max_reflection_depth = int(parse_integer(o, v, 0, 1000)); }},
      {"-f", [&](auto& o, auto& v) { cl.max_refraction_depth = int(parse_integer(o, v, 0, 1000)); }},
      {"-g", [&](auto& o, auto& v) { cl.grid_size = int(parse_integer(o, v, 0, 4096)); }},
      {"-s", [&](auto& o, auto& v) { cl.area_light_samples = int(parse_integer(o, v, 1, 1024)); }},
      {"-a", [&](auto& o, auto& v) { cl.antialias_samples = int(parse_integer(o, v, 0, 64)); }},
      {"-j", [&](auto& o, auto& v) { cl.threads = int(parse_integer(o, v, 1, 4096)); }},
      {"--threads", [&](auto& o, auto& v) { cl.threads = int(parse_integer(o, v, 1, 4096)); }},
      {"--seed", [&](auto& o, auto& v) { cl.seed = uint64_t(parse_integer(o, v, 0, kMaxInt * kMaxInt)); }},
      {"--aa-threshold", [&](auto& o, auto& v) {
         char* end = nullptr;
         const double t = std::strtod(v.c_str(), &end);
         if (v.empty() || *end != '\0' || !(t > 0 && t <= 1)) throw UsageError(o + " expects a number in (0, 1], got '" + v + "'");
         cl.antialias_threshold = float(t);
       }},
      {"--lua-memory", [&](auto& o, auto& v) { cl.load.lua_memory_bytes = parse_bytes(o, v); }},
      {"--scene-timeout", [&](auto& o, auto& v) {
         char* end = nullptr;
         const double t = std::strtod(v.c_str(), &end);
         if (v.empty() || *end != '\0' || !(t > 0 && t <= 1e6))
           throw UsageError(o + " expects a number of seconds from 0 to 1000000, got '" + v + "'");
         cl.load.timeout_seconds = t;
       }},
      {"--caustics", [&](auto& o, auto& v) { cl.caustic_photons = parse_photon_count(o, v); }},
      {"--gi", [&](auto& o, auto& v) { cl.global_photons = parse_photon_count(o, v); }},
      {"--output", [&](auto&, auto& v) { cl.output = v; }},
      {"--outdir", [&](auto&, auto& v) { cl.outdir = v; }},
      {"--stats-json", [&](auto&, auto& v) { cl.stats_json = v; }},
      {"--accel", [&](auto& o, auto& v) {
         if (v != "bvh" && v != "grid" && v != "none" && v != "embree")
           throw UsageError(o + " expects bvh, grid, none or embree, got '" + v + "'");
         cl.accel = v;
       }},
      {"--gamma", [&](auto& o, auto& v) {
         if (v != "linear" && v != "srgb") throw UsageError(o + " expects linear or srgb, got '" + v + "'");
         cl.srgb = v == "srgb";
       }},
      {"--transform-order", [&](auto& o, auto& v) {
         if (v == "pre") cl.load.transform_order = TransformOrder::kPre;
         else if (v == "post") cl.load.transform_order = TransformOrder::kPost;
         else if (v == "auto") cl.load.transform_order = TransformOrder::kAuto;
         else throw UsageError(o + " expects pre, post or auto, got '" + v + "'");
       }},
  };
  const std::map<std::string, std::function<void()>> flags = {
      {"-o", [&] { cl.optimal_grid = true; }},
      {"--stats", [&] { cl.print_stats = true; }},
      {"--quiet", [&] { cl.quiet = true; }},
      {"--resume", [&] { cl.resume = true; }},
      {"--unsafe-lua", [&] { cl.load.unsafe_lua = true; }},
      {"-h", [&] { cl.show_help = true; }},
      {"--help", [&] { cl.show_help = true; }},
      {"--version", [&] { cl.show_version = true; }},
  };

  std::vector<std::string> positional;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i], value;
    bool has_inline_value = false;
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
      value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      has_inline_value = true;
    }
    if (auto flag = flags.find(arg); flag != flags.end() && !has_inline_value) {
      flag->second();
    } else if (auto option = with_value.find(arg); option != with_value.end()) {
      if (!has_inline_value) {
        if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
        value = args[++i];
      }
      option->second(arg, value);
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else {
      positional.push_back(arg);
    }
  }
  if (cl.show_help || cl.show_version) return cl;
  if (positional.size() != 1)
    throw UsageError(positional.empty() ? "no scene file given" : "give exactly one scene file");
  cl.scene = positional[0];
  if (cl.output && cl.outdir) throw UsageError("--output and --outdir cannot be used together");
  return cl;
}

}  // namespace mjray
