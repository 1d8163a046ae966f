// What the live page is told: render ids, frames, progress, errors that leave the last good
// image in place, and the current image as PNG.

#include <regex>

#include <gtest/gtest.h>

#include "live_state.h"
#include "mjray/io/image_reader.h"
#include "support/scratch_files.h"

namespace mjray {
namespace {

Image filled(int width, int height, Color c) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = c;
  return image;
}

/// The image a PNG holds, read back through mjray's own reader.
Image decoded(const std::string& png) {
  const auto path = test::make_temp_dir("live-state") / "frame.png";
  test::write_file(path, png);
  return read_image(path);
}

bool has(const std::string& json, const std::string& text) { return json.find(text) != std::string::npos; }

TEST(LiveState, EachRenderHasANewIdAndListsItsFrames) {
  LiveState page("scene.lua", {});
  EXPECT_TRUE(has(page.status_json(), "\"render_id\": 0"));
  page.begin_render();
  EXPECT_TRUE(has(page.status_json(), "\"state\": \"loading\""));
  page.set_frames({{"a.png", 4, 3}, {"b.png", 8, 6}});
  const std::string json = page.status_json();
  EXPECT_TRUE(has(json, "\"scene\": \"scene.lua\", \"render_id\": 1, \"state\": \"rendering\""));
  EXPECT_TRUE(has(json, "{\"image\": \"a.png\", \"number\": 1, \"width\": 4, \"height\": 3, \"version\": 0"));
  EXPECT_TRUE(has(json, "{\"image\": \"b.png\", \"number\": 2, \"width\": 8, \"height\": 6"));
  EXPECT_TRUE(has(json, "\"phase\": \"waiting\", \"statistics\": null"));
  page.begin_render();
  EXPECT_EQ(page.render_id(), 2u);
}

TEST(LiveState, ProgressAndStatisticsOfAFrameAreReported) {
  LiveState page("scene.lua", {});
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}, {"b.png", 4, 3}});
  page.show_progress(1, {FramePhase::kAntialiasing, 0.5, 12, 2e6, 2});
  std::string json = page.status_json();
  EXPECT_TRUE(has(json, "\"active_frame\": 2"));
  EXPECT_TRUE(has(json, "\"progress\": 0.5000, \"eta_seconds\": 12.0, \"rays_per_second\": 2000000, "
                        "\"antialias_pass\": 2, \"phase\": \"anti-aliasing\""));
  JobStatistics stats;
  stats.image = "/home/someone/renders/b.png";  // the page shows the file name only
  stats.primitives = 7;
  page.finish_frame(1, stats);
  page.finish_render();
  json = page.status_json();
  EXPECT_TRUE(has(json, "\"state\": \"done\""));
  EXPECT_TRUE(has(json, "\"phase\": \"done\", \"statistics\": {\"image\": \"b.png\""));
  EXPECT_TRUE(has(json, "\"primitives\": 7"));
  EXPECT_FALSE(has(json, "/home/someone")) << json;
}

TEST(LiveState, TheImageIsAPngOfTheFrameAndANewOneHasANewVersion) {
  LiveState page("scene.lua", {});
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}});
  EXPECT_FALSE(page.frame_png(0));
  EXPECT_FALSE(page.frame_png(1));
  page.show_image(0, filled(4, 3, {1, 0, 0}));
  const auto first = page.frame_png(0);
  ASSERT_TRUE(first);
  const Image red = decoded(*first);
  ASSERT_EQ(red.width(), 4);
  ASSERT_EQ(red.height(), 3);
  EXPECT_EQ(red.at(3, 2).r, 1.0f);
  EXPECT_EQ(page.frame_png(0), first);  // unchanged image, same bytes
  EXPECT_TRUE(has(page.status_json(), "\"version\": 1"));
  page.show_image(0, filled(4, 3, {0, 0, 1}));
  EXPECT_TRUE(has(page.status_json(), "\"version\": 2"));
  EXPECT_EQ(decoded(*page.frame_png(0)).at(0, 0).b, 1.0f);
}

TEST(LiveState, AnErrorIsShownEscapedAndTheLastGoodImageStays) {
  LiveState page("scene.lua", {});
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}});
  page.show_image(0, filled(4, 3, {0, 1, 0}));
  const auto good = page.frame_png(0);
  page.begin_render();
  page.fail("scene.lua:3: unexpected symbol near '\"'");
  const std::string json = page.status_json();
  EXPECT_TRUE(has(json, "\"state\": \"error\", \"error\": \"scene.lua:3: unexpected symbol near '\\\"'\""));
  EXPECT_EQ(page.frame_png(0), good);
  // The script runs again: the error goes, the image stays until a new one replaces it.
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}});
  EXPECT_TRUE(has(page.status_json(), "\"error\": \"\""));
  EXPECT_EQ(page.frame_png(0), good);
  // A frame of another size is another picture: its old image goes.
  page.set_frames({{"a.png", 8, 6}});
  EXPECT_FALSE(page.frame_png(0));
}

}  // namespace
}  // namespace mjray
