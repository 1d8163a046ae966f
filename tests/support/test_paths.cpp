#include "support/test_paths.h"

#include <atomic>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace mjray::test {

std::filesystem::path source_dir() { return MJRAY_SOURCE_DIR; }

std::optional<std::filesystem::path> shared_dir() {
  if (const char* env = std::getenv("MJRAY_SHARED_DIR")) {
    if (std::filesystem::is_directory(env)) return std::filesystem::path(env);
    return std::nullopt;
  }
  const auto candidate = source_dir().parent_path() / "shared";
  if (std::filesystem::is_directory(candidate / "corpus")) return candidate;
  return std::nullopt;
}

std::filesystem::path mjray_binary() { return MJRAY_BINARY; }

std::optional<std::filesystem::path> mjray_mpi_binary() {
#ifdef MJRAY_MPI_BINARY
  if (std::filesystem::exists(MJRAY_MPI_BINARY)) return std::filesystem::path(MJRAY_MPI_BINARY);
#endif
  return std::nullopt;
}

std::optional<std::filesystem::path> mpiexec() {
#ifdef MJRAY_MPIEXEC
  if (std::filesystem::exists(MJRAY_MPIEXEC)) return std::filesystem::path(MJRAY_MPIEXEC);
#endif
  return std::nullopt;
}

std::filesystem::path make_temp_dir(const std::string& tag) {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mjray-test-" + std::to_string(::getpid()) + "-" + tag + "-" +
                    std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace mjray::test
