#include "mjray/io/atomic_file.h"

#include <array>
#include <cerrno>
#include <cstdio>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "mjray/core/error.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

/// Names drawn before giving up: a clash means another writer drew the same 64 random bits.
constexpr int kNameAttempts = 64;

std::string errno_text(int err) { return std::generic_category().message(err); }

[[noreturn]] void fail_write(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot write '" + path.string() + "': " + reason);
}

fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

/// A file descriptor closed when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  bool valid() const { return fd_ >= 0; }

 private:
  int fd_;
};

/// ".mjray-<16 hex digits>.tmp": short, so that it fits wherever the target's name fits, and
/// fresh for every draw, so that no name planted in advance can be the one used.
std::string random_temporary_name() {
  thread_local std::mt19937_64 generator{(uint64_t(std::random_device{}()) << 32) ^ std::random_device{}()};
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), ".mjray-%016llx.tmp", static_cast<unsigned long long>(generator()));
  return text.data();
}

/// Writes every byte and makes them durable; the errno of the failure, or 0.
int write_and_sync(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return errno;
    bytes.remove_prefix(size_t(written));
  }
  return ::fsync(fd) == 0 ? 0 : errno;
}

/// Errors of open(O_TMPFILE) that mean "this file system or kernel has no unnamed files".
bool unnamed_files_unsupported(int err) { return err == EOPNOTSUPP || err == EISDIR || err == EINVAL; }

/// Gives the unnamed file `fd` a fresh random name in `folder`; "" when it cannot be linked
/// (no /proc and no CAP_DAC_READ_SEARCH for AT_EMPTY_PATH). linkat never replaces a name.
std::string link_unnamed(int fd, int folder) {
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  for (int attempt = 0; attempt < kNameAttempts; ++attempt) {
    const std::string name = random_temporary_name();
    if (::linkat(AT_FDCWD, self.c_str(), folder, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return name;
    if (errno == EEXIST) continue;
    if (::linkat(fd, "", folder, name.c_str(), AT_EMPTY_PATH) == 0) return name;
    if (errno != EEXIST) return "";
  }
  return "";
}

/// Creates a file of a fresh random name in `folder`, refusing any name that exists (a link
/// included); returns its descriptor and sets `name`, or -1 with errno.
int create_named(int folder, std::string& name) {
  for (int attempt = 0; attempt < kNameAttempts; ++attempt) {
    name = random_temporary_name();
    const int fd = ::openat(folder, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

/// Why a folder cannot take files: it is missing, or the system's reason.
std::string folder_failure(const fs::path& folder, int err) {
  std::error_code ec;
  if (err == ENOENT && !fs::exists(folder, ec)) return "folder '" + folder.string() + "' does not exist";
  return "cannot create a temporary file in '" + folder.string() + "': " + errno_text(err);
}

/// Writes `bytes` to a new temporary in `folder` and returns its name there; throws OutputError.
std::string write_temporary(const fs::path& path, int folder, std::string_view bytes) {
  // Compute: an unnamed file first, named only once its bytes are durable.
  {
    const Descriptor unnamed(::openat(folder, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666));
    if (!unnamed.valid() && !unnamed_files_unsupported(errno)) fail_write(path, folder_failure(folder_of(path), errno));
    if (unnamed.valid()) {
      if (const int err = write_and_sync(unnamed.get(), bytes)) fail_write(path, "writing failed: " + errno_text(err));
      if (std::string name = link_unnamed(unnamed.get(), folder); !name.empty()) return name;
    }
  }
  // Compute: else a named file created exclusively, removed again on failure.
  std::string name;
  const Descriptor named(create_named(folder, name));
  if (!named.valid()) fail_write(path, folder_failure(folder_of(path), errno));
  if (const int err = write_and_sync(named.get(), bytes)) {
    ::unlinkat(folder, name.c_str(), 0);
    fail_write(path, "writing failed: " + errno_text(err));
  }
  return name;
}

}  // namespace

void write_file_atomically(const fs::path& path, std::string_view bytes) {
  const fs::path folder_path = folder_of(path);
  const Descriptor folder(::open(folder_path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!folder.valid()) fail_write(path, folder_failure(folder_path, errno));
  const std::string temporary = write_temporary(path, folder.get(), bytes);
  if (::renameat(folder.get(), temporary.c_str(), folder.get(), path.filename().c_str()) != 0) {
    const int err = errno;
    ::unlinkat(folder.get(), temporary.c_str(), 0);
    fail_write(path, "cannot replace it with the new file: " + errno_text(err));
  }
  // Makes the rename durable. Best effort: the new file is already in place, and some file
  // systems refuse fsync on folders.
  (void)::fsync(folder.get());
}

void check_name_fits(const fs::path& path) {
  const fs::path folder = folder_of(path);
  errno = 0;
  const long most = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const size_t length = path.filename().string().size();
  if (most > 0 && length > size_t(most))
    fail_write(path, "its name is " + std::to_string(length) + " bytes long, and the file system of '" +
                         folder.string() + "' takes at most " + std::to_string(most));
}

void check_writable_place(const fs::path& path) {
  const fs::path folder = folder_of(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) fail_write(path, "folder '" + folder.string() + "' does not exist");
  if (fs::is_directory(path, ec)) fail_write(path, "it is a folder");
  check_name_fits(path);
  const Descriptor dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (!dir.valid()) fail_write(path, "folder '" + folder.string() + "' cannot be opened: " + errno_text(errno));
  // Compute: a real file made and removed there, as the writer will make one.
  const Descriptor probe(::openat(dir.get(), ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666));
  if (probe.valid()) return;
  if (!unnamed_files_unsupported(errno)) fail_write(path, "folder '" + folder.string() + "' is not writable: " + errno_text(errno));
  std::string name;
  const Descriptor named(create_named(dir.get(), name));
  if (!named.valid()) fail_write(path, "folder '" + folder.string() + "' is not writable: " + errno_text(errno));
  ::unlinkat(dir.get(), name.c_str(), 0);
}

}  // namespace mjray
