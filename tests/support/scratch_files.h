#pragma once
/// Writing and reading the small files tests make in a scratch folder.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace mjray::test {

/// Writes `body` to `path`, creating its folders; returns the path.
inline std::filesystem::path write_file(const std::filesystem::path& path, const std::string& body) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << body;
  return path;
}

/// The whole content of a file ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A test with its own scratch folder, dir_, and write(name, body) into it.
class ScratchFolderTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::filesystem::path& name, const std::string& body) {
    return write_file(dir_ / name, body);
  }

  const std::filesystem::path dir_ = make_temp_dir("scratch");
};

}  // namespace mjray::test
