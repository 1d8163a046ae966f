#pragma once
/// What a file holds, in 16 hex digits, for the fingerprints that tell a resumed render its
/// inputs are unchanged; and the hashing of a script's input files while the script runs.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>

namespace mjray {

/// FNV-1a over a file's bytes, as hex; "missing" when it cannot be read.
std::string file_hash(const std::filesystem::path& path);

/// Hashes files on a thread of its own, in the order they are added: a scene's meshes and
/// textures are hashed while the script goes on (reading a large mesh leaves the other cores
/// idle), not after it. A file added again is hashed again only if it changed.
class BackgroundFileHashes {
 public:
  /// Its size and time of last change.
  using Stamp = std::pair<uintmax_t, std::filesystem::file_time_type>;

  BackgroundFileHashes() = default;
  /// Stops hashing at once.
  ~BackgroundFileHashes();
  BackgroundFileHashes(const BackgroundFileHashes&) = delete;
  BackgroundFileHashes& operator=(const BackgroundFileHashes&) = delete;

  /// Queues a regular file (anything else is ignored).
  void add(const std::filesystem::path& path);
  /// file_hash of each file queued, waiting for those not hashed yet. A file that changed since
  /// it was hashed, or could not be hashed, is left out: its hash is to be taken when needed.
  std::map<std::filesystem::path, std::string> wait();

 private:
  struct Hashed {
    std::string hash;
    Stamp stamp;  ///< the file's before it was read
  };
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::filesystem::path> queue_;
  std::set<std::filesystem::path> pending_;  ///< queued or being hashed
  std::map<std::filesystem::path, Hashed> hashes_;
  bool stopping_ = false;
  std::atomic<bool> stop_hashing_ = false;  ///< read while hashing, without the lock
  std::thread thread_;  ///< started by the first add
};

}  // namespace mjray
