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

/// A fresh empty folder under the system temp folder, removed by nobody (tests are small).
std::filesystem::path make_temp_dir(const std::string& tag);

}  // namespace mjray::test

/// Skips the current test, naming what is missing, when ../shared is absent.
#define MJRAY_REQUIRE_SHARED(var)                                                         \
  const auto var##_opt = ::mjray::test::shared_dir();                                     \
  if (!var##_opt) GTEST_SKIP() << "../shared (corpus and models) is absent; set "         \
                                  "MJRAY_SHARED_DIR to run this test";                    \
  const std::filesystem::path var = *var##_opt
