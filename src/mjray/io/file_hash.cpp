#include "mjray/io/file_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>

namespace mjray {

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

BackgroundFileHashes::BackgroundFileHashes() : thread_([this] { run(); }) {}

BackgroundFileHashes::~BackgroundFileHashes() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BackgroundFileHashes::add(const std::filesystem::path& path) {
  // Others (a pipe, a device) are left to be read when they are needed, as they were before.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;
  {
    std::lock_guard lock(mutex_);
    if (!hashes_.emplace(path, "").second) return;
    queue_.push_back(path);
  }
  changed_.notify_all();
}

std::map<std::filesystem::path, std::string> BackgroundFileHashes::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] {
    for (const auto& [path, hash] : hashes_)
      if (hash.empty()) return false;
    return true;
  });
  return hashes_;
}

void BackgroundFileHashes::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    const std::filesystem::path path = queue_.front();
    queue_.pop_front();
    lock.unlock();
    std::string hash = file_hash(path);
    lock.lock();
    hashes_[path] = std::move(hash);
    changed_.notify_all();
  }
}

}  // namespace mjray
