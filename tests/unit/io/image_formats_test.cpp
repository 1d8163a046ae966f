// The formats beyond CS 488's 8-bit PNG: OpenEXR (read back through OpenEXR itself), 16-bit
// PNG and JPEG, and the metadata each keeps for --resume.

#include <ImfArray.h>
#include <ImfFloatAttribute.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mjray/core/error.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"
#include "support/scratch_files.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

/// Linear values a film holds: far above 1, tiny, zero, and in between.
Image film_like_image() {
  Image image(4, 3);
  const float values[] = {0, 1e-3f, 0.25f, 0.5f, 0.999f, 1, 1.5f, 3.75f, 17.2f, 1000.5f, 60000, 0.1234567f};
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const float v = values[y * 4 + x];
      image.at(x, y) = Color(v, v * 0.5f, v * 2 > 65000 ? 1 : v * 2);
    }
  return image;
}

/// The closest half float to v, as a float.
float as_half(float v) { return float(half(v)); }

class ImageFormats : public test::ScratchFolderTest {};

TEST_F(ImageFormats, ExrKeepsLinearValuesAboveOneWithinHalfPrecision) {
  const Image image = film_like_image();
  const fs::path path = dir_ / "film.exr";
  write_image(image, path, {.render_seconds = 2.5, .metadata = {{"mjray job", "size=4x3\n-s=1\n"}}});
  // Read with OpenEXR itself, not mjray's reader.
  Imf::RgbaInputFile file(path.c_str());
  const Imath::Box2i window = file.dataWindow();
  ASSERT_EQ(window.max.x - window.min.x + 1, 4);
  ASSERT_EQ(window.max.y - window.min.y + 1, 3);
  Imf::Array2D<Imf::Rgba> pixels(3, 4);
  file.setFrameBuffer(&pixels[0][0], 1, 4);
  file.readPixels(window.min.y, window.max.y);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const Color& c = image.at(x, y);
      EXPECT_EQ(float(pixels[y][x].r), as_half(c.r)) << x << "," << y;
      EXPECT_EQ(float(pixels[y][x].g), as_half(c.g)) << x << "," << y;
      EXPECT_EQ(float(pixels[y][x].b), as_half(c.b)) << x << "," << y;
      EXPECT_LE(std::abs(float(pixels[y][x].r) - c.r), c.r * 0x1p-11f) << "half keeps 11 significant bits";
    }
  EXPECT_EQ(float(pixels[2][1].r), 1000.5f);
  // The header holds the render settings and time.
  const auto* job = file.header().findTypedAttribute<Imf::StringAttribute>("mjray job");
  ASSERT_NE(job, nullptr);
  EXPECT_EQ(job->value(), "size=4x3\n-s=1\n");
  const auto* seconds = file.header().findTypedAttribute<Imf::FloatAttribute>("renderSeconds");
  ASSERT_NE(seconds, nullptr);
  EXPECT_EQ(seconds->value(), 2.5f);
  EXPECT_NE(file.header().findTypedAttribute<Imf::StringAttribute>("capDate"), nullptr);
  // And mjray's reader gives the same values and metadata back.
  const Image back = read_image(path);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(back.at(x, y).r, as_half(image.at(x, y).r));
  bool found = false;
  for (const auto& [key, value] : read_image_metadata(path)) found |= key == "mjray job" && value == "size=4x3\n-s=1\n";
  EXPECT_TRUE(found);
  EXPECT_TRUE(holds_linear_values(path));
  EXPECT_FALSE(holds_linear_values((write_image(image, dir_ / "film.png"), dir_ / "film.png")));
}

TEST_F(ImageFormats, ExrIgnoresGammaAndRefusesABitDepth) {
  const Image image = film_like_image();
  write_image(image, dir_ / "srgb.exr", {.gamma = OutputGamma::kSrgb});
  EXPECT_EQ(read_image(dir_ / "srgb.exr").at(2, 1).r, as_half(1.5f));
  try {
    check_image_output_format(dir_ / "deep.exr", {.bit_depth = 16});
    ADD_FAILURE() << "a bit depth for EXR was accepted";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("EXR stores half floats"), std::string::npos) << e.what();
  }
}

TEST_F(ImageFormats, SixteenBitPngRoundTripKeepsEverySixteenBitCode) {
  Image image(256, 1);
  for (int x = 0; x < 256; ++x) image.at(x, 0) = Color(float(x * 257 + 1) / 65535.0f, float(x) / 255.0f, 1 - float(x) / 300.0f);
  write_image(image, dir_ / "deep.png", {.bit_depth = 16});
  const Image back = read_image(dir_ / "deep.png", {.keep_16_bits = true});
  for (int x = 0; x < 256; ++x)
    for (const auto& [a, b] : {std::pair{image.at(x, 0).r, back.at(x, 0).r}, {image.at(x, 0).g, back.at(x, 0).g},
                               {image.at(x, 0).b, back.at(x, 0).b}})
      EXPECT_EQ(b, float(to_16bit(a, OutputGamma::kLinear)) / 65535.0f) << x;
  // Codes 1 apart in 16 bits stay apart; the 8-bit read of the same file merges them.
  EXPECT_NE(back.at(0, 0).r, 0.f);
  EXPECT_EQ(read_image(dir_ / "deep.png").at(0, 0).r, 0.f);
}

TEST_F(ImageFormats, JpegQualityTradesSizeForFidelity) {
  Image image(64, 48);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      image.at(x, y) = Color(float(x) / 63, float(y) / 47, 0.5f + 0.5f * std::sin(float(x) * 0.4f) * std::cos(float(y) * 0.3f));
  double errors[2] = {0, 0};
  size_t sizes[2] = {0, 0};
  const int qualities[2] = {30, 95};
  for (int q = 0; q < 2; ++q) {
    const fs::path path = dir_ / ("q" + std::to_string(qualities[q]) + ".jpg");
    write_image(image, path, {.jpeg_quality = qualities[q]});
    sizes[q] = fs::file_size(path);
    const Image back = read_image(path);
    ASSERT_EQ(back.width(), 64);
    ASSERT_EQ(back.height(), 48);
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) errors[q] += std::abs(back.at(x, y).b - image.at(x, y).b);
  }
  EXPECT_LT(sizes[0], sizes[1]);
  EXPECT_LT(errors[1], errors[0] / 2);
  EXPECT_LT(errors[1] / (64 * 48), 0.01);
}

TEST_F(ImageFormats, JpegKeepsMetadataLongerThanOneCommentMarker) {
  std::string fingerprint;
  for (int i = 0; fingerprint.size() < 150000; ++i) fingerprint += "file input" + std::to_string(i) + ".obj=0123456789abcdef\n";
  const fs::path path = dir_ / "long.jpg";
  write_image(film_like_image(), path, {.metadata = {{"mjray job", fingerprint}, {"other", "x"}}});
  const ImageMetadata text = read_image_metadata(path);
  ASSERT_EQ(text.size(), 2u);
  EXPECT_EQ(text[0].first, "mjray job");
  EXPECT_EQ(text[0].second, fingerprint);
  EXPECT_EQ(text[1], (std::pair<std::string, std::string>{"other", "x"}));
}

TEST_F(ImageFormats, JpegRefusesSixteenBitsAndQualitiesOutOfRange) {
  for (const EncodeOptions& options : {EncodeOptions{.bit_depth = 16}, EncodeOptions{.jpeg_quality = 0},
                                       EncodeOptions{.jpeg_quality = 101}})
    EXPECT_THROW(check_image_output_format(dir_ / "x.jpg", options), OutputError);
  EXPECT_NO_THROW(check_image_output_format(dir_ / "x.JPEG", {}));
}

TEST_F(ImageFormats, EveryFormatTakesAPartialSnapshot) {
  // Incremental rewrites write unfinished tiles as black, in whatever format the output is.
  Image partial(32, 16);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 32; ++x) partial.at(x, y) = Color(0.8f, 0.4f, 0.2f);
  for (const char* name : {"p.png", "p.ppm", "p.jpg", "p.exr"}) {
    write_image(partial, dir_ / name);
    const Image back = read_image(dir_ / name);
    EXPECT_NEAR(back.at(5, 3).r, 0.8f, 0.02f) << name;
    EXPECT_NEAR(back.at(5, 12).r, 0.f, 0.02f) << name;
  }
}

}  // namespace
}  // namespace mjray
