// Every CS 488 corpus scene and every shipped scene renders, through the job library with the
// options its header names, an image that matches its stored reference (reduced to at most
// 128 pixels a side, same camera). The tolerance and how to regenerate the references after
// an intended change: support/reference_image.h.

#include <algorithm>
#include <sstream>

#include <gtest/gtest.h>

#include "cli.h"
#include "mjray/lua/scene_loader.h"
#include "support/corpus_scenes.h"
#include "support/reference_image.h"
#include "support/test_job.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

constexpr int kMaxSide = 128;

/// The command line of a scene's header, as the program reads it.
CommandLine header_command_line(const std::filesystem::path& scene) {
  std::vector<std::string> args;
  std::istringstream words(test::header_options(scene));
  for (std::string word; words >> word;) args.push_back(word);
  args.push_back(scene.string());
  return parse_command_line(args);
}

/// Renders every job of `script` reduced to kMaxSide and compares each with reference
/// `name` (`name_N` for the N-th of several jobs).
void expect_references(const std::filesystem::path& script, const std::string& name) {
  const CommandLine cl = header_command_line(script);
  SceneDescription scene = load_scene(script, cl.load);
  JobOptions options = job_options(cl);
  options.outputs = {};
  for (RenderJob& job : scene.jobs) {
    // Keep the camera and aspect ratio; shrink the image.
    const double shrink = std::min(1.0, double(kMaxSide) / std::max(job.width, job.height));
    job.width = std::max(1, int(job.width * shrink));
    job.height = std::max(1, int(job.height * shrink));
  }
  for (size_t i = 0; i < scene.jobs.size(); ++i) {
    const Image image = test::TestJob(scene, i, options).render();
    const std::string id = scene.jobs.size() > 1 ? name + "_" + std::to_string(i + 1) : name;
    EXPECT_TRUE(test::matches_reference(image, id));
  }
}

class CorpusReference : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusReference, MatchesItsReferenceImage) {
  MJRAY_REQUIRE_SHARED(shared);
  expect_references(shared / "corpus/cs488" / GetParam(), "corpus/" + test::identifier(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Golden, CorpusReference, ::testing::ValuesIn(test::corpus_scenes()),
                         [](const auto& info) { return test::identifier(info.param); });

class ShippedReference : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(ShippedReference, MatchesItsReferenceImage) {
  expect_references(GetParam(), "scenes/" + GetParam().stem().string());
}

INSTANTIATE_TEST_SUITE_P(Golden, ShippedReference, ::testing::ValuesIn(test::shipped_scenes()),
                         [](const auto& info) { return info.param.stem().string(); });

}  // namespace
}  // namespace mjray
