// Every CS 488 corpus scene renders unchanged through the real program, into an image of the
// size it asks for. What the images show is checked against references in
// reference_images_test.cpp.

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

struct CorpusScene {
  const char* path;  ///< under shared/corpus/cs488/
  const char* image; ///< the file its gr.render names
  int width;
  int height;
};

const CorpusScene kScenes[] = {
    {"hmhealey-cs488a4/data/hier.lua", "hier.png", 256, 256},
    {"hmhealey-cs488a4/data/instance.lua", "instance.png", 256, 256},
    {"hmhealey-cs488a4/data/macho-cows.lua", "macho_cows.png", 256, 256},
    {"hmhealey-cs488a4/data/nonhier.lua", "nonhier.png", 256, 256},
    {"hmhealey-cs488a4/data/nonhier2.lua", "nonhier.png", 256, 256},
    {"hmhealey-cs488a4/data/sample.lua", "island.png", 1024, 1024},
    {"hmhealey-cs488a4/data/simple-cows.lua", "simple_cows.png", 256, 256},
    {"hmhealey-cs488a4/data/simple.lua", "simple.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/hier.lua", "hier.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/instance.lua", "instance.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/macho-cows.lua", "macho-cows.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/mucho-macho-cows.lua", "real-macho-cows-newview.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/nonhier.lua", "nonhier.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/nonhier2.lua", "nonhier.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/sample.lua", "sample.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/simple-cows.lua", "simple-cows.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/simple.lua", "simple.png", 512, 512},
};

class CorpusRender : public ::testing::TestWithParam<CorpusScene> {};

TEST_P(CorpusRender, RendersUnchangedToTheSizeItAsksFor) {
  MJRAY_REQUIRE_SHARED(shared);
  const CorpusScene& scene = GetParam();
  const auto script = shared / "corpus/cs488" / scene.path;
  ASSERT_TRUE(std::filesystem::exists(script)) << script;
  const auto out = test::make_temp_dir("corpus");
  const auto log = out / "stderr.txt";
  const std::string command = "'" + test::mjray_binary().native() + "' --quiet --outdir '" + out.string() +
                              "' '" + script.string() + "' 2> '" + log.string() + "'";
  const int status = std::system(command.c_str());
  std::ifstream log_stream(log);
  const std::string messages((std::istreambuf_iterator<char>(log_stream)), {});
  ASSERT_EQ(status, 0) << messages;

  const Image image = read_image(out / scene.image);
  EXPECT_EQ(image.width(), scene.width);
  EXPECT_EQ(image.height(), scene.height);
  std::filesystem::remove_all(out);
}

std::string scene_name(const ::testing::TestParamInfo<CorpusScene>& info) {
  std::string name = info.param.path;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRender, ::testing::ValuesIn(kScenes), scene_name);

}  // namespace
}  // namespace mjray
