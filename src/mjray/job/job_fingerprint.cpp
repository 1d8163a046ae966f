#include "mjray/job/job_fingerprint.h"

#include "mjray/io/file_hash.h"
#include "mjray/job/job_camera.h"
#include "mjray/job/option_table.h"

#include <charconv>
#include <cstdio>
#include <map>
#include <sstream>

namespace mjray {

namespace {

/// The shortest text that reads back as `value`.
std::string float_text(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
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

JobFingerprints::JobFingerprints(const SceneDescription& scene, const JobOptions& options)
    : scene_(scene), options_(options) {
  inputs_ = "scene " + scene.script.filename().string() + "=" + file_hash(scene.script) + "\n";
  // Paths relative to the scene's folder: the fingerprint travels in every image's metadata,
  // and must not tell whoever receives one where its maker keeps files.
  const std::filesystem::path scene_folder = std::filesystem::absolute(scene.script).parent_path().lexically_normal();
  for (const auto& input : scene.inputs) {
    const auto known = scene.input_hashes.find(input);
    const std::string name = std::filesystem::absolute(input).lexically_normal().lexically_relative(scene_folder).string();
    inputs_ += "file " + name + "=" + (known != scene.input_hashes.end() ? known->second : file_hash(input)) + "\n";
  }
  for (const auto& [name, value] : scene.defines) inputs_ += "-D " + name + "=" + value + "\n";
}

std::string JobFingerprints::of(size_t index) const {
  const RenderJob& job = scene_.jobs[index];
  const JobOptions& o = options_;
  std::string text = inputs_;
  const auto line = [&](const std::string& name, const std::string& value) { text += name + "=" + value + "\n"; };
  line("gr.render call", std::to_string(index + 1) + " of " + std::to_string(scene_.jobs.size()));
  const ImageSize size = job_image_size(job, o.view);
  line("size", std::to_string(size.width) + "x" + std::to_string(size.height));
  line("transform order", job.post_multiplied ? "post" : "pre");
  line("anti-aliasing passes", std::to_string(o.render.antialias_max_passes));
  const CameraDescription camera = job_camera(job, o.view);
  line("lens", camera.aperture_radius > 0 ? "aperture " + float_text(camera.aperture_radius) + ", focus " + float_text(camera.focus_distance)
                                          : "pinhole");
  // Every option that changes the pixels or their encoding, as the option table records it.
  for (const OptionSpec& spec : option_table())
    if (spec.fingerprint) line(spec.names.back(), spec.fingerprint(o));
  return text;
}

std::string job_fingerprint(const SceneDescription& scene, size_t index, const JobOptions& options) {
  return JobFingerprints(scene, options).of(index);
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
