// What the live page is told: render ids, frames, progress, errors that leave the last good
// image in place, and the current image as PNG.

#include <cmath>
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

/// The status as the page reads it.
Json status(const LiveState& page) { return Json::parse(page.status_json()); }

TEST(LiveState, EachRenderHasANewIdAndListsItsFrames) {
  LiveState page("scene.lua", {});
  EXPECT_EQ(status(page)["render_id"], 0);
  page.begin_render();
  EXPECT_EQ(status(page)["state"], "loading");
  page.set_frames({{"a.png", 4, 3}, {"b.png", 8, 6}});
  const Json json = status(page);
  EXPECT_EQ(json["scene"], "scene.lua");
  EXPECT_EQ(json["render_id"], 1);
  EXPECT_EQ(json["state"], "rendering");
  ASSERT_EQ(json["frames"].size(), 2u);
  EXPECT_EQ(json["frames"][0], (Json{{"image", "a.png"}, {"number", 1}, {"width", 4}, {"height", 3}, {"version", 0},
                                     {"progress", 0.0}, {"eta_seconds", 0.0}, {"rays_per_second", 0.0},
                                     {"antialias_pass", 0}, {"phase", "waiting"}, {"statistics", nullptr}}));
  EXPECT_EQ(json["frames"][1]["image"], "b.png");
  EXPECT_EQ(json["frames"][1]["number"], 2);
  EXPECT_EQ(json["frames"][1]["width"], 8);
  page.begin_render();
  EXPECT_EQ(page.render_id(), 2u);
}

TEST(LiveState, ProgressAndStatisticsOfAFrameAreReported) {
  LiveState page("scene.lua", {});
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}, {"b.png", 4, 3}});
  page.show_progress(1, {FramePhase::kAntialiasing, 0.5, 12, 2e6, 2});
  Json json = status(page);
  EXPECT_EQ(json["active_frame"], 2);
  const Json& frame = json["frames"][1];
  EXPECT_EQ(frame["progress"], 0.5);
  EXPECT_EQ(frame["eta_seconds"], 12.0);
  EXPECT_EQ(frame["rays_per_second"], 2e6);
  EXPECT_EQ(frame["antialias_pass"], 2);
  EXPECT_EQ(frame["phase"], "anti-aliasing");
  JobStatistics stats;
  stats.image = "/home/someone/renders/b.png";  // the page shows the file name only
  stats.primitives = 7;
  page.finish_frame(1, stats);
  page.finish_render();
  json = status(page);
  EXPECT_EQ(json["state"], "done");
  EXPECT_EQ(json["frames"][1]["phase"], "done");
  EXPECT_EQ(json["frames"][1]["statistics"]["image"], "b.png");
  EXPECT_EQ(json["frames"][1]["statistics"]["primitives"], 7);
  EXPECT_FALSE(has(page.status_json(), "/home/someone")) << json;
}

TEST(LiveState, TheStatusIsValidJsonWhateverTheNamesAndNumbersHold) {
  // Bytes that are not UTF-8, control characters and a NaN: still one parseable object.
  LiveState page("sce\xffne\n\x01.lua", {});
  page.begin_render();
  page.set_frames({{"a\x80.png", 4, 3}});
  page.show_progress(0, {FramePhase::kFirstPass, std::nan(""), 1, 0, 0});
  page.fail("line 1: \x1b[2J \"quoted\" \xc3");
  const Json json = status(page);
  EXPECT_TRUE(json["frames"][0]["progress"].is_null());
  EXPECT_EQ(json["error"].get<std::string>().substr(0, 7), "line 1:");
  EXPECT_EQ(json["scene"], "sce\xef\xbf\xbdne\n\x01.lua");
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
  EXPECT_EQ(status(page)["frames"][0]["version"], 1);
  page.show_image(0, filled(4, 3, {0, 0, 1}));
  EXPECT_EQ(status(page)["frames"][0]["version"], 2);
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
  const Json json = status(page);
  EXPECT_EQ(json["state"], "error");
  EXPECT_EQ(json["error"], "scene.lua:3: unexpected symbol near '\"'");
  EXPECT_EQ(page.frame_png(0), good);
  // The script runs again: the error goes, the image stays until a new one replaces it.
  page.begin_render();
  page.set_frames({{"a.png", 4, 3}});
  EXPECT_EQ(status(page)["error"], "");
  EXPECT_EQ(page.frame_png(0), good);
  // A frame of another size is another picture: its old image goes.
  page.set_frames({{"a.png", 8, 6}});
  EXPECT_FALSE(page.frame_png(0));
}

}  // namespace
}  // namespace mjray
