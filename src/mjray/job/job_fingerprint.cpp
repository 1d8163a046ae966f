#include "mjray/job/job_fingerprint.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace mjray {

namespace {

/// FNV-1a over a file's bytes, as hex; "missing" when it cannot be read.
std::string file_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "missing";
  uint64_t hash = 0xcbf29ce484222325ULL;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    for (std::streamsize i = 0; i < in.gcount(); ++i) hash = (hash ^ static_cast<unsigned char>(buffer[i])) * 0x100000001b3ULL;
  }
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

std::map<std::string, std::string> lines_of(const std::string& text) {
  std::map<std::string, std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const size_t eq = line.find('=');
    if (eq != std::string::npos) lines[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return lines;
}

}  // namespace

std::string job_fingerprint(const SceneDescription& scene, size_t index, const JobOptions& o) {
  const RenderJob& job = scene.jobs[index];
  std::string text;
  const auto line = [&](const std::string& name, const std::string& value) { text += name + "=" + value + "\n"; };
  line("scene " + scene.script.filename().string(), file_hash(scene.script));
  for (const auto& input : scene.inputs) line("file " + input.string(), file_hash(input));
  line("gr.render call", std::to_string(index + 1) + " of " + std::to_string(scene.jobs.size()));
  line("size", std::to_string(job.width) + "x" + std::to_string(job.height));
  line("transform order", job.post_multiplied ? "post" : "pre");
  line("-r", std::to_string(o.integrator.max_reflection_depth));
  line("-f", std::to_string(o.integrator.max_refraction_depth));
  line("-s", std::to_string(o.integrator.area_light_samples));
  line("-a", std::to_string(o.render.antialias_samples));
  line("--aa-threshold", number(o.render.antialias_threshold));
  line("anti-aliasing passes", std::to_string(o.render.antialias_max_passes));
  line("--seed", std::to_string(o.render.seed));
  // Only when on, so that states saved before these options existed still resume.
  if (o.photons.caustics()) line("--caustics", std::to_string(o.photons.caustic_photons));
  if (o.photons.global_illumination()) line("--gi", std::to_string(o.photons.global_photons));
  line("tile size", std::to_string(o.render.tile_size));
  return text;
}

std::string fingerprint_difference(const std::string& saved, const std::string& current) {
  const auto before = lines_of(saved), now = lines_of(current);
  std::string differences;
  const auto add = [&](const std::string& text) { differences += (differences.empty() ? "" : "; ") + text; };
  for (const auto& [name, value] : now) {
    const auto it = before.find(name);
    if (it == before.end()) add(name + " is new");
    else if (it->second != value) add(name.rfind("file ", 0) == 0 || name.rfind("scene ", 0) == 0 ? name + " changed" : name + ": " + it->second + " then, " + value + " now");
  }
  for (const auto& [name, value] : before)
    if (!now.count(name)) add(name + " is no longer read");
  return differences;
}

}  // namespace mjray
