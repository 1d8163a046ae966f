#pragma once
/// Running the mjray program from a test and reading what it said.

#include <filesystem>
#include <string>
#include <vector>

namespace mjray::test {

/// What one run of the program did.
struct ProgramRun {
  int exit_code = -1;  ///< -1 when it did not exit normally
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

/// `text` quoted for sh.
std::string shell_quoted(const std::string& text);

/// Runs `ENVIRONMENT mjray ARGS` in `folder` with stdin from /dev/null, capturing both streams
/// (`environment` is put before the command as is, e.g. "PATH=/nowhere").
ProgramRun run_mjray(const std::vector<std::string>& args, const std::filesystem::path& folder = "/",
                     const std::string& environment = "");

}  // namespace mjray::test
