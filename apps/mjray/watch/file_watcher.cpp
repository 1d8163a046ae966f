#include "file_watcher.h"

#include <algorithm>
#include <thread>

#include <sys/stat.h>

namespace mjray {

FileWatcher::Stamp FileWatcher::stamp_of(const std::filesystem::path& file) {
  struct stat s {};
  if (::stat(file.c_str(), &s) != 0) return {};
  const auto ns = [](const timespec& t) { return int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec; };
  return {true, uint64_t(s.st_ino), uint64_t(s.st_size), ns(s.st_mtim), ns(s.st_ctim)};
}

void FileWatcher::watch(const std::vector<std::filesystem::path>& files) {
  std::vector<std::pair<std::filesystem::path, Stamp>> next;
  for (const auto& file : files) {
    if (std::any_of(next.begin(), next.end(), [&](const auto& f) { return f.first == file; })) continue;
    const auto known = std::find_if(files_.begin(), files_.end(), [&](const auto& f) { return f.first == file; });
    next.emplace_back(file, known != files_.end() ? known->second : stamp_of(file));
  }
  files_ = std::move(next);
}

bool FileWatcher::changed() const {
  return std::any_of(files_.begin(), files_.end(), [](const auto& f) { return stamp_of(f.first) != f.second; });
}

void FileWatcher::accept() {
  for (auto& [file, stamp] : files_) stamp = stamp_of(file);
}

bool FileWatcher::wait_for_change(std::chrono::milliseconds poll, const std::function<bool()>& give_up) const {
  while (!give_up()) {
    if (changed()) return true;
    std::this_thread::sleep_for(poll);
  }
  return false;
}

bool FileWatcher::settle(std::chrono::milliseconds quiet, const std::function<bool()>& give_up) {
  // Sleep in short steps so that give_up() is heard at once.
  constexpr auto kStep = std::chrono::milliseconds(20);
  for (;;) {
    accept();
    for (auto slept = std::chrono::milliseconds(0); slept < quiet; slept += kStep) {
      if (give_up()) return false;
      std::this_thread::sleep_for(kStep);
    }
    if (!changed()) return true;
  }
}

}  // namespace mjray
