#pragma once
/// Notices when the script or a file it read changes, by polling: cheap for the few files a
/// scene reads, and it sees editors that save by replacing the file as well as those that
/// write in place.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

namespace mjray {

/// A set of files and the state each was last accepted in.
class FileWatcher {
 public:
  /// Watches exactly `files` from now on: a file already watched keeps its accepted state
  /// (so a change made since is still noticed), a new one is taken as it is now.
  void watch(const std::vector<std::filesystem::path>& files);
  /// Whether any watched file differs from its accepted state (appeared, vanished, rewritten).
  bool changed() const;
  /// Takes every watched file as it is now.
  void accept();

  /// Polls every `poll` until a file changes (true) or `give_up()` says so (false).
  bool wait_for_change(std::chrono::milliseconds poll, const std::function<bool()>& give_up) const;
  /// Accepts the files, then waits until they have stayed unchanged for `quiet`, so that a
  /// burst of saves counts as one; false when `give_up()` said so first.
  bool settle(std::chrono::milliseconds quiet, const std::function<bool()>& give_up);

 private:
  /// What identifies one version of a file.
  struct Stamp {
    bool exists = false;
    uint64_t inode = 0, size = 0;
    int64_t modified_ns = 0, changed_ns = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp_of(const std::filesystem::path& file);

  std::vector<std::pair<std::filesystem::path, Stamp>> files_;
};

}  // namespace mjray
