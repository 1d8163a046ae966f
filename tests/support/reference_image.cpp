#include "support/reference_image.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"
#include "mjray/lua/scene_loader.h"
#include "support/corpus_scenes.h"
#include "support/test_job.h"
#include "support/test_paths.h"

namespace mjray::test {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& folder : {source_dir() / "scenes", source_dir() / "scenes/features", source_dir() / "docs/images"})
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".lua") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string header_options(const fs::path& scene) {
  std::ifstream in(scene);
  std::string line;
  // An option, then maybe its value: a number, a word or a path, but never the scene itself.
  const std::regex render(
      R"(Render: +(?:build/mjray|\./render\.sh)((?: +-[-a-zA-Z]+(?: +(?!\S*\.lua(?:\s|$))[a-z0-9./_][-a-z0-9./_,:]*(?=\s|$))?)*))");
  for (int i = 0; i < 10 && std::getline(in, line); ++i) {
    std::smatch m;
    if (std::regex_search(line, m, render)) return m[1];
  }
  return "";
}

::testing::AssertionResult matches_reference(const Image& image, const std::string& name) {
  const fs::path path = source_dir() / "tests/golden/references" / (name + ".png");
  const char* update = std::getenv("MJRAY_UPDATE_REFERENCES");
  if (update && std::string(update) == "1") {
    fs::create_directories(path.parent_path());
    write_image(image, path);
    return ::testing::AssertionSuccess() << "wrote " << path;
  }
  if (!fs::exists(path))
    return ::testing::AssertionFailure() << "no reference " << path << " (run scripts/update_references.sh)";
  const Image reference = read_image(path);
  if (reference.width() != image.width() || reference.height() != image.height())
    return ::testing::AssertionFailure() << name << ": " << image.width() << "x" << image.height()
                                         << ", the reference is " << reference.width() << "x" << reference.height();
  size_t off = 0;
  double total = 0;
  int worst = 0, worst_x = 0, worst_y = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Color& a = image.at(x, y);
      const Color& b = reference.at(x, y);
      int pixel = 0;
      for (const auto& [va, vb] : {std::pair{a.r, b.r}, std::pair{a.g, b.g}, std::pair{a.b, b.b}}) {
        const int d = std::abs(int(to_8bit(va, OutputGamma::kLinear)) - int(to_8bit(vb, OutputGamma::kLinear)));
        total += d;
        pixel = std::max(pixel, d);
      }
      if (pixel > kPixelTolerance) ++off;
      if (pixel > worst) worst = pixel, worst_x = x, worst_y = y;
    }
  const double pixels = double(image.width()) * image.height();
  const double mean = total / (3 * pixels);
  if (double(off) <= kMaxOffPixelShare * pixels && mean <= kMeanTolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << name << ": " << off << " of " << size_t(pixels) << " pixels differ by more than "
                                       << kPixelTolerance << " levels, mean difference " << mean
                                       << " levels, worst " << worst << " at (" << worst_x << ", " << worst_y
                                       << "); compare with " << path;
}

namespace {

constexpr int kMaxSide = 128;

/// The command line of a scene's header, as the program reads it.
CommandLine header_command_line(const fs::path& scene) {
  std::vector<std::string> args;
  std::istringstream words(header_options(scene));
  for (std::string word; words >> word;) args.push_back(word);
  args.push_back(scene.string());
  return parse_command_line(args);
}

}  // namespace

void expect_references(const fs::path& script, const std::string& name, const std::vector<size_t>& jobs) {
  CommandLine cl = header_command_line(script);
  // As the program runs them, from the repository's root (docs/images' scenes read scenes/Assets).
  cl.run.load.allowed_read_folders.push_back(test::source_dir());
  SceneDescription scene = load_scene(script, cl.run.load);
  JobOptions options = cl.run.job;
  options.outputs = {};
  for (RenderJob& job : scene.jobs) {
    // Keep the camera and aspect ratio; shrink the image.
    const double shrink = std::min(1.0, double(kMaxSide) / std::max(job.width, job.height));
    job.width = std::max(1, int(job.width * shrink));
    job.height = std::max(1, int(job.height * shrink));
  }
  std::vector<size_t> chosen = jobs;
  if (chosen.empty())
    for (size_t i = 0; i < scene.jobs.size(); ++i) chosen.push_back(i);
  for (const size_t i : chosen) {
    const Image image = TestJob(scene, i, options).render();
    const std::string id = scene.jobs.size() > 1 ? name + "_" + std::to_string(i + 1) : name;
    EXPECT_TRUE(matches_reference(image, id));
  }
}

}  // namespace mjray::test
