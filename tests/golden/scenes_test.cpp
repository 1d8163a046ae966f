// Every scene the project ships (scenes/*.lua, scenes/features/*.lua) renders with the options
// its header names, into a non-blank image.

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& folder : {test::source_dir() / "scenes", test::source_dir() / "scenes/features"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".lua") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

/// The options of the header's "Render: build/mjray OPTIONS scenes/..." line.
std::string header_options(const std::filesystem::path& scene) {
  std::ifstream in(scene);
  std::string line;
  const std::regex render(R"(Render: +(?:build/mjray|\./render\.sh)((?: +-[-a-z]+(?: +[0-9.]+)?)*))");
  for (int i = 0; i < 10 && std::getline(in, line); ++i) {
    std::smatch m;
    if (std::regex_search(line, m, render)) return m[1];
  }
  return "";
}

class ShippedScene : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(ShippedScene, RendersIntoANonBlankImage) {
  const auto& scene = GetParam();
  const auto out = test::make_temp_dir("scene");
  const auto log = out / "log.txt";
  const std::string command = "'" + test::mjray_binary().string() + "' --quiet" + header_options(scene) +
                              " --outdir '" + out.string() + "' '" + scene.string() + "' 2> '" + log.string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command << "\n" << std::ifstream(log).rdbuf();
  int images = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    if (entry.path().extension() != ".png") continue;
    ++images;
    const Image image = read_image(entry.path());
    std::set<std::tuple<float, float, float>> colours;
    for (const Color& c : image.pixels()) colours.insert({c.r, c.g, c.b});
    EXPECT_GT(colours.size(), 100u) << entry.path() << " looks blank";
  }
  EXPECT_GE(images, 1);
  std::filesystem::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Golden, ShippedScene, ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return info.param.stem().string(); });

}  // namespace
}  // namespace mjray
