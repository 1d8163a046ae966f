#pragma once
/// Watches a running render from a second thread: shows progress on stderr, rewrites the
/// image with the finished tiles every few seconds, and stops it when the user interrupts
/// (interrupts.h) or when --time-limit's deadline passes.

#include <atomic>
#include <chrono>
#include <optional>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>

#include "progress_estimate.h"
#include "mjray/io/image_codec.h"
#include "mjray/render/image_render.h"

namespace mjray {

/// How the watcher reports.
struct WatchOptions {
  bool quiet = false;                   ///< no progress output (warnings still print)
  double snapshot_interval_seconds = 5; ///< incremental image rewrites; 0 = never
  EncodeOptions encoding;               ///< of the incremental image rewrites
  RenderSettings render;                ///< of the render watched, for the estimate of its work
  int width = 0, height = 0;            ///< of the pixels it traces (ImageRender::region())
  std::string frame;                    ///< "frame 7/24" in animations, shown before the progress
  /// --time-limit: when to stop the render (none: only an interrupt stops it).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

/// Runs while it lives; the destructor stops the thread and prints the final 100% line.
class RenderWatcher {
 public:
  RenderWatcher(ImageRender& render, std::filesystem::path image_path, WatchOptions options);
  ~RenderWatcher();
  /// Marks the render finished so the last progress line says 100%.
  void finish() { finished_ = true; }
  /// Whether the watcher stopped the render because the deadline passed.
  bool timed_out() const { return timed_out_; }

 private:
  void loop();
  void report(double elapsed, bool final);

  ImageRender& render_;
  std::filesystem::path image_path_;
  WatchOptions options_;
  bool terminal_;
  // Set when the render ends; wakes the watcher at once, not at its next tick.
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  bool done_ = false;  // guarded by wake_mutex_
  std::atomic<bool> finished_{false};
  std::atomic<bool> timed_out_{false};
  ProgressEstimate estimate_;
  double shown_fraction_ = 0;  // the most the bar has shown
  int last_percent_ = -1;      // of the last line without a terminal
  std::string last_stage_;     // the stage the last line named ("" for none)
  double last_line_at_ = 0;    // its time
  std::thread thread_;
};

}  // namespace mjray
