#pragma once
/// What a file holds, in 16 hex digits, for the fingerprints that tell a resumed render its
/// inputs are unchanged; and the hashing of a script's input files while the script runs.

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace mjray {

/// FNV-1a over a file's bytes, as hex; "missing" when it cannot be read.
std::string file_hash(const std::filesystem::path& path);

/// Hashes files on a thread of its own, in the order they are added: a scene's meshes and
/// textures are hashed while the script goes on (reading a large mesh leaves the other cores
/// idle), not after it. A file added twice is hashed once.
class BackgroundFileHashes {
 public:
  BackgroundFileHashes();
  /// Stops after the file being hashed, if any.
  ~BackgroundFileHashes();
  BackgroundFileHashes(const BackgroundFileHashes&) = delete;
  BackgroundFileHashes& operator=(const BackgroundFileHashes&) = delete;

  /// Queues a regular file (anything else is ignored).
  void add(const std::filesystem::path& path);
  /// file_hash of every file queued, waiting for those not hashed yet.
  std::map<std::filesystem::path, std::string> wait();

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::filesystem::path> queue_;
  std::map<std::filesystem::path, std::string> hashes_;  ///< "" while queued or being hashed
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace mjray
