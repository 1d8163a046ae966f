#include "mjray/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "mjray/core/error.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

std::string errno_text(int err) { return std::generic_category().message(err); }

[[noreturn]] void fail_write(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot write '" + path.string() + "': " + reason);
}

/// The temporary sibling of an output file: removed unless committed over the target.
class TempFile {
 public:
  explicit TempFile(fs::path path) : path_(std::move(path)) {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
      open_errno_ = errno;
      return;
    }
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
      open_errno_ = errno;
      ::close(fd);
      discard();
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (file_ != nullptr) std::fclose(file_);
    if (!committed_ && open_errno_ == 0) discard();
  }

  FILE* file() const { return file_; }
  int open_errno() const { return open_errno_; }

  /// Flushes, fsyncs, closes and renames over `target`; returns the reason on failure.
  std::string commit(const fs::path& target) {
    const auto failed = [&](const char* step) {
      return std::string(step) + " '" + path_.filename().string() + "' failed: " + errno_text(errno);
    };
    if (std::fflush(file_) != 0) return failed("writing");
    if (::fsync(::fileno(file_)) != 0) return failed("syncing");
    FILE* file = file_;
    file_ = nullptr;
    if (std::fclose(file) != 0) return failed("closing");
    if (std::rename(path_.c_str(), target.c_str()) != 0)
      return "cannot replace it with '" + path_.filename().string() + "': " + errno_text(errno);
    committed_ = true;
    sync_folder();
    return {};
  }

 private:
  void discard() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }

  // Makes the rename durable. Best effort: the new file is already in place, and some
  // filesystems refuse fsync on folders.
  void sync_folder() const {
    const fs::path folder = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
  }

  fs::path path_;
  FILE* file_ = nullptr;
  int open_errno_ = 0;
  bool committed_ = false;
};

std::string create_failure(const fs::path& tmp, int err) {
  const fs::path folder = tmp.has_parent_path() ? tmp.parent_path() : fs::path(".");
  std::error_code ec;
  if (err == ENOENT && !fs::exists(folder, ec)) return "folder '" + folder.string() + "' does not exist";
  return "cannot create temporary file '" + tmp.filename().string() + "': " + errno_text(err);
}

}  // namespace

void write_file_atomically(const fs::path& path, std::string_view bytes) {
  fs::path tmp_path = path;
  tmp_path += ".tmp-" + std::to_string(::getpid());
  TempFile tmp(tmp_path);
  if (tmp.file() == nullptr) fail_write(path, create_failure(tmp_path, tmp.open_errno()));
  if (std::fwrite(bytes.data(), 1, bytes.size(), tmp.file()) != bytes.size()) fail_write(path, errno_text(errno));
  if (const std::string reason = tmp.commit(path); !reason.empty()) fail_write(path, reason);
}

void check_writable_place(const fs::path& path) {
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) fail_write(path, "folder '" + folder.string() + "' does not exist");
  if (fs::is_directory(path, ec)) fail_write(path, "it is a folder");
  if (::access(folder.c_str(), W_OK) != 0) fail_write(path, "folder '" + folder.string() + "' is not writable");
}

}  // namespace mjray
