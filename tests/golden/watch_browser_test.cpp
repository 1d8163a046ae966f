// A real browser on the live page: headless Chromium loads it from a running `mjray --watch`,
// and its screenshot must show the rendered image, pixel for pixel.

#include <chrono>
#include <csignal>
#include <optional>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "support/background_process.h"
#include "support/chromium_devtools.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"
#include "support/watch_run.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

/// Debian's chromium (scripts/setup.sh installs it).
std::optional<fs::path> chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (fs::exists(p)) return fs::path(p);
  return std::nullopt;
}

/// Where `image` appears whole in `screen` (each channel within 2/255), if it does.
std::optional<std::pair<int, int>> find_image(const Image& screen, const Image& image) {
  constexpr float kTolerance = 2.5f / 255;
  const auto same = [&](const Color& a, const Color& b) {
    return std::abs(a.r - b.r) <= kTolerance && std::abs(a.g - b.g) <= kTolerance && std::abs(a.b - b.b) <= kTolerance;
  };
  for (int y0 = 0; y0 + image.height() <= screen.height(); ++y0)
    for (int x0 = 0; x0 + image.width() <= screen.width(); ++x0) {
      bool match = true;
      for (int y = 0; y < image.height() && match; ++y)
        for (int x = 0; x < image.width() && match; ++x) match = same(screen.at(x0 + x, y0 + y), image.at(x, y));
      if (match) return std::pair{x0, y0};
    }
  return std::nullopt;
}

/// A checkered sphere in colours `a` and `b` (Lua tables) before a grey background: nothing
/// else on the page looks like it.
std::string checkered_sphere(const std::string& a, const std::string& b) {
  return "local root = gr.node('root')\n"
         "local m = gr.material({0.8, 0.2, 0.6}, {0.3, 0.3, 0.3}, 20)\n"
         "m:set_material_texture(gr.checkerboardtexture(" + a + ", " + b + ", 2))\n"
         "local s = gr.nh_sphere('s', {0, 0, 0}, 1)\n"
         "s:set_material(m)\n"
         "root:add_child(s)\n"
         "gr.render(root, 'out.png', 160, 120, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},\n"
         "  {gr.light({3, 4, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
}

/// Takes screenshots of `page` until one shows `image` (true) or `timeout` passes (false).
bool wait_until_shown(test::ChromiumPage& page, const Image& image, const fs::path& screenshot,
                      std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    const std::string png = page.screenshot();
    if (!png.empty()) {
      test::write_file(screenshot, png);
      if (find_image(read_image(screenshot), image)) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

TEST(GoldenWatchBrowser, ChromiumShowsTheRenderedImageOnThePage) {
  const auto browser = chromium();
  ASSERT_TRUE(browser) << "chromium is missing: scripts/setup.sh installs it";
  const auto dir = test::make_temp_dir("watch-browser");
  // A checkered sphere before the sky's gradient: nothing else on the page looks like it.
  test::write_file(dir / "scene.lua", checkered_sphere("{0.9, 0.1, 0.5}", "{0.2, 0.1, 0.8}"));
  test::WatchRun w({"--quiet", (dir / "scene.lua").string()}, dir / "log.txt");
  ASSERT_TRUE(w.serving()) << w.process().log();
  ASSERT_TRUE(w.wait_until_done()) << w.process().log();
  const Image rendered = read_image(dir / "out.png");

  // Load the page as a person would, in a fresh profile, and let its script fetch the image.
  const fs::path screenshot = dir / "screen.png";
  test::BackgroundProcess chromium_run({browser->string(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                                   "--no-first-run", "--disable-background-networking", "--disable-component-update",
                                   "--disable-sync", "--hide-scrollbars", "--force-device-scale-factor=1",
                                   "--force-color-profile=srgb", "--user-data-dir=" + (dir / "profile").string(),
                                   "--window-size=800,600", "--virtual-time-budget=4000",
                                   "--screenshot=" + screenshot.string(), w.url()},
                                  dir / "chromium.txt");
  EXPECT_EQ(chromium_run.wait(test::kPatience), 0) << chromium_run.log();
  ASSERT_TRUE(fs::exists(screenshot)) << test::read_file(dir / "chromium.txt");
  const Image screen = read_image(screenshot);
  ASSERT_EQ(screen.width(), 800);
  ASSERT_EQ(screen.height(), 600);

  const auto at = find_image(screen, rendered);
  ASSERT_TRUE(at) << "the screenshot " << screenshot << " does not show the image " << dir / "out.png";
  w.process().signal(SIGINT);
  EXPECT_EQ(w.process().wait(test::kPatience), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mjray

namespace mjray {
namespace {

// The page as it is left open: the browser loads it once, and after a save of the script the
// page itself (its polling script, no reload) brings the new render's image on screen.
TEST(GoldenWatchBrowser, AnOpenPageShowsTheNewImageAfterTheScriptIsSaved) {
  const auto browser = chromium();
  ASSERT_TRUE(browser) << "chromium is missing: scripts/setup.sh installs it";
  const auto dir = test::make_temp_dir("watch-browser-live");
  test::write_file(dir / "scene.lua", checkered_sphere("{0.9, 0.1, 0.5}", "{0.2, 0.1, 0.8}"));
  test::WatchRun w({"--quiet", (dir / "scene.lua").string()}, dir / "log.txt");
  ASSERT_TRUE(w.serving()) << w.process().log();
  const auto first = w.wait_until_done();
  ASSERT_TRUE(first) << w.process().log();
  const Image before = read_image(dir / "out.png");

  test::ChromiumPage page(*browser, dir / "profile", dir / "chromium.txt", 800, 600);
  ASSERT_TRUE(page.ok()) << test::read_file(dir / "chromium.txt");
  ASSERT_TRUE(page.navigate(w.url())) << test::read_file(dir / "chromium.txt");
  ASSERT_TRUE(wait_until_shown(page, before, dir / "screen1.png", test::kPatience))
      << "the page never showed the first image; last screenshot " << dir / "screen1.png" << "\n"
      << test::read_file(dir / "chromium.txt");

  // Save other colours: a new render, and the open page follows it.
  test::write_file(dir / "scene.lua", checkered_sphere("{0.1, 0.8, 0.2}", "{0.9, 0.8, 0.1}"));
  ASSERT_TRUE(w.wait_until_done(first->render_id, test::kPatience)) << w.process().log();
  const Image after = read_image(dir / "out.png");
  ASSERT_NE(after.at(80, 60).g, before.at(80, 60).g);
  ASSERT_TRUE(wait_until_shown(page, after, dir / "screen2.png", test::kPatience))
      << "the open page never showed the new image; last screenshot " << dir / "screen2.png" << "\n"
      << w.process().log() << test::read_file(dir / "chromium.txt");
  EXPECT_FALSE(find_image(read_image(dir / "screen2.png"), before));

  w.process().signal(SIGINT);
  EXPECT_EQ(w.process().wait(test::kPatience), 0) << w.process().log();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mjray
