#include "live_state.h"

#include <filesystem>

#include "mjray/io/png_codec.h"

namespace mjray {

namespace {

const char* phase_name(FramePhase phase) {
  switch (phase) {
    case FramePhase::kWaiting: return "waiting";
    case FramePhase::kCoarse: return "coarse";
    case FramePhase::kFirstPass: return "first pass";
    case FramePhase::kAntialiasing: return "anti-aliasing";
    case FramePhase::kDone: return "done";
  }
  return "waiting";
}

}  // namespace

LiveState::LiveState(std::string scene_name, const EncodeOptions& encoding)
    : scene_name_(std::move(scene_name)), encoding_(encoding) {
  // The page gets an ordinary 8-bit image with no text chunks, whatever the output is.
  encoding_.bit_depth = 8;
  encoding_.metadata.clear();
}

void LiveState::begin_render() {
  std::lock_guard lock(mutex_);
  ++render_id_;
  state_ = "loading";
  active_frame_ = 0;
}

void LiveState::set_frames(const std::vector<FrameDescription>& frames) {
  std::lock_guard lock(mutex_);
  frames_.resize(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    Frame& f = frames_[i];
    // An image of another size belongs to a different frame: drop it.
    if (f.description.width != frames[i].width || f.description.height != frames[i].height) {
      f.image.reset();
      f.version = 0;
    }
    f.description = frames[i];
    f.progress = {};
    f.statistics.clear();
  }
  error_.clear();
  state_ = "rendering";
}

void LiveState::fail(const std::string& message) {
  std::lock_guard lock(mutex_);
  error_ = message;
  state_ = "error";
}

void LiveState::show_image(size_t frame, Image image) {
  std::lock_guard lock(mutex_);
  if (frame >= frames_.size()) return;
  frames_[frame].image = std::make_shared<const Image>(std::move(image));
  frames_[frame].version = next_version_++;
}

void LiveState::show_progress(size_t frame, const FrameProgress& progress) {
  std::lock_guard lock(mutex_);
  if (frame >= frames_.size()) return;
  frames_[frame].progress = progress;
  active_frame_ = frame;
}

void LiveState::finish_frame(size_t frame, const JobStatistics& statistics) {
  std::lock_guard lock(mutex_);
  if (frame >= frames_.size()) return;
  frames_[frame].progress = {FramePhase::kDone, 1, 0, statistics.rays_per_second(), 0};
  // The page names the output by its file name only: where this machine keeps it is none of
  // a viewer's business (with --listen the viewer may be anyone).
  JobStatistics shown = statistics;
  shown.image = std::filesystem::path(shown.image).filename().string();
  frames_[frame].statistics = statistics_object(shown);
}

void LiveState::finish_render() {
  std::lock_guard lock(mutex_);
  state_ = "done";
}

uint64_t LiveState::render_id() const {
  std::lock_guard lock(mutex_);
  return render_id_;
}

std::string LiveState::status_json() const {
  std::lock_guard lock(mutex_);
  Json frames = Json::array();
  for (size_t i = 0; i < frames_.size(); ++i) {
    const Frame& f = frames_[i];
    frames.push_back({{"image", f.description.image},
                      {"number", i + 1},
                      {"width", f.description.width},
                      {"height", f.description.height},
                      {"version", f.version},
                      {"progress", f.progress.fraction},
                      {"eta_seconds", f.progress.eta_seconds},
                      {"rays_per_second", f.progress.rays_per_second},
                      {"antialias_pass", f.progress.antialias_pass},
                      {"phase", phase_name(f.progress.phase)},
                      {"statistics", f.statistics}});
  }
  return json_text({{"scene", scene_name_},
                    {"render_id", render_id_},
                    {"state", state_},
                    {"error", error_},
                    {"active_frame", active_frame_ + 1},
                    {"frames", std::move(frames)}});
}

std::optional<std::string> LiveState::frame_png(size_t frame) const {
  std::shared_ptr<const Image> image;
  uint64_t version = 0;
  {
    std::lock_guard lock(mutex_);
    if (frame >= frames_.size() || !frames_[frame].image) return std::nullopt;
    const Frame& f = frames_[frame];
    if (f.png && f.png_version == f.version) return *f.png;
    image = f.image;
    version = f.version;
  }
  // Encode outside the lock; keep the bytes while the image is current.
  auto png = std::make_shared<const std::string>(encode_png(*image, encoding_));
  std::lock_guard lock(mutex_);
  if (frame < frames_.size() && frames_[frame].version == version) {
    frames_[frame].png = png;
    frames_[frame].png_version = version;
  }
  return *png;
}

}  // namespace mjray
