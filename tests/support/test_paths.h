#pragma once
/// Where tests find their inputs: the project's own files and the shared read-only inputs
/// (../shared beside the checkout: corpus scenes and real meshes).

#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

namespace mjray::test {

/// The project's source tree.
std::filesystem::path source_dir();

/// ../shared beside the checkout (or $MJRAY_SHARED_DIR), when present.
std::optional<std::filesystem::path> shared_dir();

/// The built mjray program.
std::filesystem::path mjray_binary();

/// The built mjray-mpi program and the mpirun that starts it, when MPI was found at configure
/// time and mpirun is still there.
std::optional<std::filesystem::path> mjray_mpi_binary();
std::optional<std::filesystem::path> mpiexec();

/// A fresh empty folder under the system temp folder, removed by nobody (tests are small).
std::filesystem::path make_temp_dir(const std::string& tag);

}  // namespace mjray::test

/// Skips the current test, naming what is missing, when ../shared is absent.
#define MJRAY_REQUIRE_SHARED(var)                                                         \
  const auto var##_opt = ::mjray::test::shared_dir();                                     \
  if (!var##_opt) GTEST_SKIP() << "../shared (corpus and models) is absent; set "         \
                                  "MJRAY_SHARED_DIR to run this test";                    \
  const std::filesystem::path var = *var##_opt

/// Skips the current test, saying why, when mjray-mpi was not built or mpirun is missing
/// (scripts/setup.sh installs Open MPI, so this is rare).
#define MJRAY_REQUIRE_MPI()                                                                  \
  if (!::mjray::test::mjray_mpi_binary() || !::mjray::test::mpiexec())                       \
  GTEST_SKIP() << "mjray-mpi or mpirun is absent (Open MPI not installed when configured); " \
                  "run scripts/setup.sh to install it"
