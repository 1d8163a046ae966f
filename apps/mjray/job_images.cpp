#include "job_images.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "mjray/core/error.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/job/job_fingerprint.h"

namespace mjray {

namespace {

constexpr const char* kFingerprintKey = "mjray job";
/// Why a partial image stopped and how far it got.
constexpr const char* kStoppedKey = "mjray stopped";

/// The fingerprint a finished image records, or "" when it records none.
std::string recorded_fingerprint(const std::filesystem::path& image) {
  for (const auto& [key, value] : read_image_metadata(image))
    if (key == kFingerprintKey) return value;
  return "";
}

/// With --resume and a complete image (no state beside it): true when this scene and these
/// options made it; else throws SceneError saying what differs.
bool complete_image_matches(const std::filesystem::path& image, const std::string& fingerprint) {
  const std::string recorded = recorded_fingerprint(image);
  const std::string advice = "; render without --resume to start again, or remove the image to render just it again";
  if (recorded.empty())
    throw SceneError(image.string() + ": --resume keeps a complete image only when it records the scene and options "
                     "that made it, and this one records none (a partial image whose state file is gone, or not "
                     "written by mjray)" + advice);
  if (recorded != fingerprint)
    throw SceneError(image.string() + ": --resume keeps a complete image only when this scene and these options made "
                     "it, and a different scene or different options made this one (" +
                     fingerprint_difference(recorded, fingerprint) + ")" + advice);
  return true;
}

}  // namespace

ResumePlan plan_resume(const std::filesystem::path& image, const std::string& fingerprint, bool resume) {
  ResumePlan plan;
  if (!resume) return plan;
  const auto state_path = checkpoint_path(image);
  std::error_code ec;
  if (std::filesystem::exists(state_path, ec)) {
    plan.state = read_checkpoint(state_path, [&](const std::string& saved) {
      if (saved != fingerprint)
        throw SceneError(state_path.string() + ": this resume state was saved by a different scene or different options (" +
                         fingerprint_difference(saved, fingerprint) + "); render without --resume to start again");
    });
    return plan;
  }
  plan.keep = std::filesystem::exists(image, ec) && complete_image_matches(image, fingerprint);
  return plan;
}

void write_finished_image(const Image& image, const std::filesystem::path& path, EncodeOptions encoding,
                          const std::string& fingerprint) {
  encoding.metadata.emplace_back(kFingerprintKey, fingerprint);
  write_image(image, path, encoding);
  // The state of an earlier, interrupted render of this image is done with; a file of that
  // name that is not mjray's is the user's, and stays.
  if (is_checkpoint_file(checkpoint_path(path))) {
    std::error_code ec;
    std::filesystem::remove(checkpoint_path(path), ec);
  }
}

std::string progress_reached(const RenderCheckpoint& checkpoint, bool targets_noise, int passes) {
  if (checkpoint.antialias_pass == 0) {
    const auto done = std::count(checkpoint.tile_done.begin(), checkpoint.tile_done.end(), uint8_t(1));
    return "first pass, " + std::to_string(done) + " of " + std::to_string(checkpoint.tile_done.size()) + " tiles";
  }
  const std::string pass = std::to_string(checkpoint.antialias_pass) + " of " + std::to_string(passes);
  if (!targets_noise) return "anti-aliasing pass " + pass;
  if (checkpoint.pass_pixels.empty()) return "noise pass " + pass + ", before its pixels were chosen";
  const auto left = std::count(checkpoint.pass_done.begin(), checkpoint.pass_done.end(), uint8_t(0));
  return "noise pass " + pass + ", " + std::to_string(left) + " of its " + std::to_string(checkpoint.pass_pixels.size()) +
         " pixels to refine";
}

void write_stopped_image(const RenderCheckpoint& checkpoint, const std::filesystem::path& path, EncodeOptions encoding,
                         StopReason reason, const std::string& reached) {
  const char* why = reason == StopReason::kTimeLimit ? "time limit" : "interrupted";
  encoding.metadata.emplace_back(kStoppedKey, std::string(why) + " in the " + reached);
  write_image(checkpoint.film.resolve(), path, encoding);
  write_checkpoint(checkpoint, checkpoint_path(path));
  std::fprintf(stderr, "mjray: %s: wrote the partial image %s (%s) and its state; run again with --resume to %s\n", why,
               path.string().c_str(), reached.c_str(), reason == StopReason::kTimeLimit ? "go on" : "finish");
}

}  // namespace mjray
