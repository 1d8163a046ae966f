#include "mjray/io/file_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>

namespace mjray {

namespace {

/// FNV-1a over a file's bytes, as hex: "missing" when it cannot be read, nothing when `stop`
/// turns true first.
std::optional<std::string> hash_unless_stopped(const std::filesystem::path& path, const std::atomic<bool>* stop) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "missing";
  uint64_t hash = 0xcbf29ce484222325ULL;
  char buffer[1 << 16];
  while (in) {
    if (stop && stop->load(std::memory_order_relaxed)) return std::nullopt;
    in.read(buffer, sizeof buffer);
    for (std::streamsize i = 0; i < in.gcount(); ++i) hash = (hash ^ static_cast<unsigned char>(buffer[i])) * 0x100000001b3ULL;
  }
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

/// What tells that a file changed after it was hashed.
BackgroundFileHashes::Stamp stamp_of(const std::filesystem::path& path) {
  std::error_code size_error, time_error;
  const auto size = std::filesystem::file_size(path, size_error);
  const auto time = std::filesystem::last_write_time(path, time_error);
  return {size_error ? 0 : size, time_error ? std::filesystem::file_time_type{} : time};
}

}  // namespace

std::string file_hash(const std::filesystem::path& path) { return *hash_unless_stopped(path, nullptr); }

BackgroundFileHashes::~BackgroundFileHashes() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    stop_hashing_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void BackgroundFileHashes::add(const std::filesystem::path& path) {
  // Others (a pipe, a device) are left to be read when they are needed, as they were before.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;
  {
    std::lock_guard lock(mutex_);
    if (pending_.contains(path)) return;
    if (const auto known = hashes_.find(path); known != hashes_.end()) {
      if (known->second.stamp == stamp_of(path)) return;
      hashes_.erase(known);  // changed since: hashed again
    }
    try {
      queue_.push_back(path);
      pending_.insert(path);
      if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    } catch (const std::exception&) {
      // No memory or no thread: the hash is taken when it is needed instead.
      std::erase(queue_, path);
      pending_.erase(path);
      return;
    }
  }
  changed_.notify_all();
}

std::map<std::filesystem::path, std::string> BackgroundFileHashes::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return pending_.empty(); });
  std::map<std::filesystem::path, std::string> result;
  for (const auto& [path, hashed] : hashes_)
    if (hashed.stamp == stamp_of(path)) result.emplace(path, hashed.hash);  // else: changed since, hashed when needed
  return result;
}

void BackgroundFileHashes::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    const std::filesystem::path path = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    std::optional<Hashed> hashed;
    try {
      const Stamp before = stamp_of(path);
      if (const auto hash = hash_unless_stopped(path, &stop_hashing_)) hashed = Hashed{*hash, before};
    } catch (const std::exception&) {
      // Left out: hashed when it is needed.
    }
    lock.lock();
    try {
      if (hashed) hashes_.insert_or_assign(path, std::move(*hashed));
    } catch (const std::exception&) {
      // Left out: hashed when it is needed.
    }
    pending_.erase(path);
    changed_.notify_all();
  }
}

}  // namespace mjray
