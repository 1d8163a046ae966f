#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"
#include "mjray/io/png_codec.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::vector<uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> file_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  return names;
}

bool has_temp_file(const fs::path& dir) {
  for (const auto& name : file_names(dir))
    if (name.find(".tmp") != std::string::npos) return true;
  return false;
}

/// Channel value k/255 whose 8-bit code is exactly k.
float code(int k) { return float(k) / 255.0f; }

/// A 5x3 image whose 45 channel codes are all distinct, so any swap or flip shows.
Image distinct_image() {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const int k = 3 * (y * 5 + x);
      image.at(x, y) = Color(code(5 * k + 1), code(5 * k + 2), code(5 * k + 3));
    }
  return image;
}

/// Pseudo-random pixels that zlib cannot shrink.
Image noise_image(int width, int height) {
  Image image(width, height);
  uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return code(int(state >> 24));
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = Color(next(), next(), next());
  return image;
}

void expect_same_pixels(const Image& expected, const Image& actual) {
  ASSERT_EQ(actual.width(), expected.width());
  ASSERT_EQ(actual.height(), expected.height());
  for (int y = 0; y < expected.height(); ++y)
    for (int x = 0; x < expected.width(); ++x)
      EXPECT_EQ(actual.at(x, y), expected.at(x, y)) << "pixel " << x << "," << y;
}

std::string write_error(const Image& image, const fs::path& path) {
  try {
    write_image(image, path);
  } catch (const OutputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// Lowers the process's file-size limit so writes fail with EFBIG, standing in for a full disk.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    active_ = ::setrlimit(RLIMIT_FSIZE, &lowered) == 0;
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, old_handler_);
  }
  bool active() const { return active_; }

 private:
  rlimit saved_{};
  void (*old_handler_)(int) = nullptr;
  bool active_ = false;
};

// --- quantisation ---------------------------------------------------------------------------

TEST(ImageWriterQuantise, LinearEndpointsAndRounding) {
  EXPECT_EQ(to_8bit(0.0f, OutputGamma::kLinear), 0);
  EXPECT_EQ(to_8bit(1.0f, OutputGamma::kLinear), 255);
  EXPECT_EQ(to_8bit(0.5f, OutputGamma::kLinear), 128);
  EXPECT_EQ(to_8bit(0.25f, OutputGamma::kLinear), 64);
  EXPECT_EQ(to_8bit(0.75f, OutputGamma::kLinear), 191);
  EXPECT_EQ(to_8bit(code(1), OutputGamma::kLinear), 1);
  EXPECT_EQ(to_8bit(code(254), OutputGamma::kLinear), 254);
}

TEST(ImageWriterQuantise, EveryValueRoundsAsTheFormulaSays) {
  // The documented rule, v·255 + 0.5 rounded down in float, against the quantiser's own
  // arithmetic: on a fine sweep of [0, 1] and one float either side of every code's edge.
  const auto formula = [](float v) { return int(std::min(255.0f, std::floor(v * 255.0f + 0.5f))); };
  for (const OutputGamma gamma : {OutputGamma::kLinear, OutputGamma::kSrgb}) {
    const auto encoded = [&](float linear) { return gamma == OutputGamma::kSrgb ? srgb_encode(linear) : linear; };
    for (int i = 1; i < 1 << 20; ++i) {
      const float linear = float(i) / float(1 << 20);
      ASSERT_EQ(to_8bit(linear, gamma), formula(encoded(linear))) << linear;
    }
  }
  for (int code_value = 0; code_value < 255; ++code_value) {
    const float edge = (float(code_value) + 0.5f) / 255.0f;
    for (const float v : {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 1.0f)}) {
      if (v > 0 && v < 1) {
        EXPECT_EQ(to_8bit(v, OutputGamma::kLinear), formula(v)) << v;
      }
    }
  }
}

TEST(ImageWriterQuantise, ClampsOutOfRangeAndNaN) {
  for (const OutputGamma gamma : {OutputGamma::kLinear, OutputGamma::kSrgb}) {
    EXPECT_EQ(to_8bit(-0.25f, gamma), 0);
    EXPECT_EQ(to_8bit(-kInf, gamma), 0);
    EXPECT_EQ(to_8bit(1.5f, gamma), 255);
    EXPECT_EQ(to_8bit(1000.0f, gamma), 255);
    EXPECT_EQ(to_8bit(kInf, gamma), 255);
    EXPECT_EQ(to_8bit(kNaN, gamma), 0);
  }
}

TEST(ImageWriterQuantise, SrgbKnownPoints) {
  EXPECT_EQ(to_8bit(0.0f, OutputGamma::kSrgb), 0);
  EXPECT_EQ(to_8bit(1.0f, OutputGamma::kSrgb), 255);
  EXPECT_EQ(to_8bit(0.5f, OutputGamma::kSrgb), 188);
  EXPECT_EQ(to_8bit(0.18f, OutputGamma::kSrgb), 118);  // middle grey
  EXPECT_EQ(to_8bit(0.2f, OutputGamma::kSrgb), 124);
  EXPECT_EQ(to_8bit(0.001f, OutputGamma::kSrgb), 3);  // linear toe: 12.92 * v
}

// --- formats --------------------------------------------------------------------------------

TEST(ImageWriterFormat, PngRoundTripIsExact) {
  const fs::path path = test::make_temp_dir("png-roundtrip") / "out.png";
  const Image image = distinct_image();
  write_image(image, path);
  const auto bytes = read_bytes(path);
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 8),
            (std::vector<uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
  expect_same_pixels(image, read_image(path));
}

/// The chunks of a PNG file after its signature: (type, data), each CRC checked.
std::vector<std::pair<std::string, std::string>> png_chunks(const std::string& png) {
  std::vector<std::pair<std::string, std::string>> chunks;
  const auto word = [&](size_t at) {
    return uint32_t(uint8_t(png[at])) << 24 | uint32_t(uint8_t(png[at + 1])) << 16 | uint32_t(uint8_t(png[at + 2])) << 8 |
           uint32_t(uint8_t(png[at + 3]));
  };
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = word(at);
    EXPECT_LE(at + 12 + length, png.size());
    const uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(png.data() + at + 4), length + 4));
    EXPECT_EQ(word(at + 8 + length), crc) << png.substr(at + 4, 4);
    chunks.emplace_back(png.substr(at + 4, 4), png.substr(at + 8, length));
    at += 12 + length;
  }
  return chunks;
}

TEST(ImageWriterFormat, PngChunksAreTheHeaderTheColourTagTheTextTheDataAndTheEnd) {
  EncodeOptions options;
  options.gamma = OutputGamma::kSrgb;
  options.metadata = {{"mjray job", "scene a.lua\n-s=4"}, {"Comment", ""}};
  const std::string png = encode_png(noise_image(300, 2), options);
  ASSERT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
  const auto chunks = png_chunks(png);
  ASSERT_EQ(chunks.size(), 6u);
  EXPECT_EQ(chunks[0].first, "IHDR");
  // 300 × 2, 8 bits, RGB, deflate, the standard filters, not interlaced.
  EXPECT_EQ(chunks[0].second, std::string("\0\0\x01\x2c\0\0\0\x02\x08\x02\0\0\0", 13));
  EXPECT_EQ(chunks[1], (std::pair<std::string, std::string>{"sRGB", std::string(1, '\0')}));
  EXPECT_EQ(chunks[2], (std::pair<std::string, std::string>{"tEXt", std::string("mjray job\0scene a.lua\n-s=4", 26)}));
  EXPECT_EQ(chunks[3], (std::pair<std::string, std::string>{"tEXt", std::string("Comment\0", 8)}));
  EXPECT_EQ(chunks[4].first, "IDAT");
  EXPECT_EQ(chunks[5], (std::pair<std::string, std::string>{"IEND", ""}));
  // Linear output carries no colour chunk.
  options.gamma = OutputGamma::kLinear;
  for (const auto& [type, data] : png_chunks(encode_png(noise_image(3, 3), options))) EXPECT_NE(type, "sRGB");
}

TEST(ImageWriterFormat, PngBytesDoNotDependOnTheThreadsThatCompressThem) {
  // Big enough for several strips of compression; 16 bits doubles the rows' bytes.
  const Image image = noise_image(700, 300);
  for (const int bits : {8, 16}) {
    EncodeOptions options;
    options.bit_depth = bits;
    const std::string serial = encode_png(image, options);
    for (const int threads : {2, 3, 8}) {
      options.threads = threads;
      EXPECT_EQ(encode_png(image, options), serial) << bits << " bits, " << threads << " threads";
    }
    const fs::path path = test::make_temp_dir("png-threads") / "out.png";
    test::write_file(path, serial);
    expect_same_pixels(image, read_image(path));
  }
}

TEST(ImageWriterFormat, PngRefusesATextKeyItCannotStore) {
  EncodeOptions options;
  for (const std::string& key : {std::string(), std::string(80, 'k'), std::string("a\0b", 3)}) {
    options.metadata = {{key, "value"}};
    EXPECT_THROW(encode_png(distinct_image(), options), OutputError) << key.size();
  }
}

TEST(ImageWriterFormat, PpmRoundTripIsExact) {
  const fs::path path = test::make_temp_dir("ppm-roundtrip") / "out.ppm";
  const Image image = distinct_image();
  write_image(image, path);
  expect_same_pixels(image, read_image(path));
}

TEST(ImageWriterFormat, PpmBytesAreExact) {
  const fs::path path = test::make_temp_dir("ppm-bytes") / "out.ppm";
  Image image(3, 2);
  image.at(0, 0) = Color(1, 0, 0);
  image.at(1, 0) = Color(0, 1, 0);
  image.at(2, 0) = Color(0, 0, 1);
  image.at(0, 1) = Color(0.5f, 0.25f, 0.75f);
  image.at(1, 1) = Color(2.0f, -1.0f, kNaN);
  image.at(2, 1) = Color(code(7), code(200), code(13));
  write_image(image, path);
  const std::string header = "P6\n3 2\n255\n";
  std::vector<uint8_t> expected(header.begin(), header.end());
  for (const int v : {255, 0, 0, 0, 255, 0, 0, 0, 255, 128, 64, 191, 255, 0, 0, 7, 200, 13})
    expected.push_back(uint8_t(v));
  EXPECT_EQ(read_bytes(path), expected);
}

TEST(ImageWriterFormat, ExtensionIsCaseInsensitive) {
  const fs::path dir = test::make_temp_dir("ext-case");
  const Image image = distinct_image();
  write_image(image, dir / "OUT.PNG");
  write_image(image, dir / "out.Ppm");
  EXPECT_EQ(read_bytes(dir / "OUT.PNG").at(1), 'P');
  EXPECT_EQ(read_bytes(dir / "out.Ppm").at(0), 'P');
  EXPECT_EQ(read_bytes(dir / "out.Ppm").at(1), '6');
  expect_same_pixels(image, read_image(dir / "OUT.PNG"));
  expect_same_pixels(image, read_image(dir / "out.Ppm"));
}

TEST(ImageWriterFormat, SrgbGammaAppliesToFileValues) {
  const fs::path dir = test::make_temp_dir("srgb");
  Image image(2, 1);
  image.at(0, 0) = Color(0.5f, 0.18f, 1.0f);
  image.at(1, 0) = Color(0.0f, 0.001f, 0.2f);
  const Image expected_png = [&] {
    Image e(2, 1);
    e.at(0, 0) = Color(code(188), code(118), code(255));
    e.at(1, 0) = Color(code(0), code(3), code(124));
    return e;
  }();
  write_image(image, dir / "out.png", {OutputGamma::kSrgb});
  write_image(image, dir / "out.ppm", {OutputGamma::kSrgb});
  expect_same_pixels(expected_png, read_image(dir / "out.png"));
  expect_same_pixels(expected_png, read_image(dir / "out.ppm"));
}

TEST(ImageWriterFormat, UnknownExtensionIsRejected) {
  const fs::path dir = test::make_temp_dir("unknown-ext");
  const fs::path path = dir / "out.xyz";
  EXPECT_EQ(write_error(distinct_image(), path),
            "cannot write '" + path.string() +
                "': unsupported image format '.xyz' (mjray writes .png, .ppm, .jpg, .jpeg, .exr)");
  EXPECT_EQ(write_error(distinct_image(), dir / "noext"),
            "cannot write '" + (dir / "noext").string() +
                "': unsupported image format '' (mjray writes .png, .ppm, .jpg, .jpeg, .exr)");
  EXPECT_TRUE(file_names(dir).empty());
}

TEST(ImageWriterFormat, EmptyImageIsRejected) {
  const fs::path dir = test::make_temp_dir("empty");
  EXPECT_EQ(write_error(Image(), dir / "out.png"),
            "cannot write '" + (dir / "out.png").string() + "': image has no pixels (0x0)");
  EXPECT_TRUE(file_names(dir).empty());
}

// --- failures and atomicity -----------------------------------------------------------------

TEST(ImageWriterFailure, MissingFolderNamesThePath) {
  const fs::path dir = test::make_temp_dir("missing");
  const fs::path path = dir / "nope" / "out.png";
  EXPECT_EQ(write_error(distinct_image(), path),
            "cannot write '" + path.string() + "': folder '" + (dir / "nope").string() +
                "' does not exist");
}

TEST(ImageWriterFailure, ParentIsARegularFile) {
  const fs::path dir = test::make_temp_dir("parent-file");
  std::ofstream(dir / "plain.txt") << "not a folder\n";
  const fs::path path = dir / "plain.txt" / "out.ppm";
  const std::string message = write_error(distinct_image(), path);
  EXPECT_EQ(message.rfind("cannot write '" + path.string() + "': ", 0), 0u) << message;
  EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
}

TEST(ImageWriterFailure, ReadOnlyFolder) {
  const fs::path dir = test::make_temp_dir("read-only");
  ASSERT_EQ(::chmod(dir.c_str(), 0555), 0);
  if (::access(dir.c_str(), W_OK) == 0) {
    ::chmod(dir.c_str(), 0755);
    GTEST_SKIP() << "permissions are not enforced for this user (root)";
  }
  const fs::path path = dir / "out.png";
  const std::string message = write_error(distinct_image(), path);
  ::chmod(dir.c_str(), 0755);
  EXPECT_EQ(message.rfind("cannot write '" + path.string() + "': ", 0), 0u) << message;
  EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  EXPECT_TRUE(file_names(dir).empty());
}

TEST(ImageWriterFailure, DiskFullKeepsPreviousFileAndNoTemp) {
  // 64x64 noise (~12 KB) overflows the limit inside fwrite; 16x16 noise (~800 bytes) stays in
  // the stdio buffer and overflows only at the final flush.
  struct Case {
    const char* name;
    int side;
    rlim_t limit;
  };
  for (const Case& c : {Case{"out.png", 64, 4096}, Case{"out.ppm", 64, 4096},
                        Case{"out.png", 16, 300}, Case{"out.ppm", 16, 300}}) {
    SCOPED_TRACE(std::string(c.name) + " side " + std::to_string(c.side));
    const fs::path dir = test::make_temp_dir("disk-full");
    const fs::path path = dir / c.name;
    write_image(distinct_image(), path);
    const auto before = read_bytes(path);
    ASSERT_FALSE(before.empty());

    std::string message;
    {
      FileSizeLimit limit(c.limit);
      ASSERT_TRUE(limit.active());
      message = write_error(noise_image(c.side, c.side), path);
    }
    EXPECT_EQ(message.rfind("cannot write '" + path.string() + "': ", 0), 0u) << message;
    EXPECT_NE(message.find("File too large"), std::string::npos) << message;
    EXPECT_EQ(read_bytes(path), before);
    EXPECT_FALSE(has_temp_file(dir));
    EXPECT_EQ(file_names(dir), std::vector<std::string>{c.name});
  }
}

TEST(ImageWriterFailure, FailedRenameRemovesTemp) {
  const fs::path dir = test::make_temp_dir("rename-fails");
  const fs::path path = dir / "out.ppm";
  fs::create_directory(path);  // rename(2) cannot replace a folder with a file
  const std::string message = write_error(distinct_image(), path);
  EXPECT_EQ(message.rfind("cannot write '" + path.string() + "': cannot replace it", 0), 0u)
      << message;
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_FALSE(has_temp_file(dir));
}

TEST(ImageWriterTemporaries, PlantedLinksCannotRedirectTheWrite) {
  // A scene folder that ships links where a temporary might be named must not get its bytes
  // written through them: every name a writer could have used before (<name>.tmp-<pid>) and a
  // link in every temporary-looking place point at a file outside.
  const fs::path dir = test::make_temp_dir("planted-links");
  const fs::path outside = test::make_temp_dir("planted-links-victim") / "victim.sh";
  std::ofstream(outside) << "#!/bin/sh\necho untouched\n";
  const auto victim_before = read_bytes(outside);
  const fs::path path = dir / "x.ppm";
  for (pid_t pid = std::max<pid_t>(1, ::getpid() - 50); pid < ::getpid() + 200; ++pid)
    fs::create_symlink(outside, dir / ("x.ppm.tmp-" + std::to_string(pid)));
  fs::create_symlink(outside, dir / ".mjray-0000000000000000.tmp");
  write_image(distinct_image(), path);
  expect_same_pixels(distinct_image(), read_image(path));
  EXPECT_FALSE(fs::is_symlink(path));
  EXPECT_EQ(read_bytes(outside), victim_before);
  size_t links = 0;
  for (const auto& entry : fs::directory_iterator(dir)) links += entry.is_symlink();
  EXPECT_EQ(links, 251u);
  EXPECT_EQ(file_names(dir).size(), 252u);  // the links and the image: no temporary left
}

TEST(ImageWriterTemporaries, ALinkAtTheTargetIsReplacedNotFollowed) {
  const fs::path dir = test::make_temp_dir("target-link");
  const fs::path outside = test::make_temp_dir("target-link-victim") / "victim.txt";
  std::ofstream(outside) << "keep me\n";
  fs::create_symlink(outside, dir / "out.png");
  write_image(distinct_image(), dir / "out.png");
  EXPECT_FALSE(fs::is_symlink(dir / "out.png"));
  expect_same_pixels(distinct_image(), read_image(dir / "out.png"));
  EXPECT_EQ(read_bytes(outside), (std::vector<uint8_t>{'k', 'e', 'e', 'p', ' ', 'm', 'e', '\n'}));
}

TEST(ImageWriterPlace, ANameTooLongForTheFileSystemIsRefusedBeforeWriting) {
  const fs::path dir = test::make_temp_dir("long-name");
  const long most = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  ASSERT_GT(most, 20);
  const fs::path fits = dir / (std::string(size_t(most) - 4, 'a') + ".png");
  EXPECT_NO_THROW(check_writable_place(fits));
  // The image's name fits, but its resume state's ("<image>.mjray-state") would not.
  try {
    check_name_fits(fits.string() + ".mjray-state");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("takes at most " + std::to_string(most)), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_writable_place(dir / (std::string(size_t(most), 'b') + ".png")), OutputError);
  EXPECT_TRUE(file_names(dir).empty());
}

TEST(ImageWriterPlace, AFolderThatTakesNoFilesIsFoundBeforeWriting) {
  const fs::path dir = test::make_temp_dir("place-read-only");
  ASSERT_EQ(::chmod(dir.c_str(), 0555), 0);
  if (::access(dir.c_str(), W_OK) == 0) {
    ::chmod(dir.c_str(), 0755);
    GTEST_SKIP() << "permissions are not enforced for this user (root)";
  }
  std::string message;
  try {
    check_writable_place(dir / "out.png");
  } catch (const OutputError& e) {
    message = e.what();
  }
  ::chmod(dir.c_str(), 0755);
  EXPECT_NE(message.find("is not writable: Permission denied"), std::string::npos) << message;
}

TEST(ImageWriterFailure, OverwriteReplacesContent) {
  const fs::path dir = test::make_temp_dir("overwrite");
  for (const char* name : {"out.png", "out.ppm"}) {
    SCOPED_TRACE(name);
    const fs::path path = dir / name;
    write_image(noise_image(7, 4), path);
    const auto first = read_bytes(path);
    const Image second = distinct_image();
    write_image(second, path);
    EXPECT_NE(read_bytes(path), first);
    expect_same_pixels(second, read_image(path));
  }
  EXPECT_FALSE(has_temp_file(dir));
  EXPECT_EQ(file_names(dir).size(), 2u);
}

// --- reading --------------------------------------------------------------------------------

TEST(ImageWriterRead, MissingFileThrows) {
  const fs::path path = test::make_temp_dir("read-missing") / "absent.png";
  try {
    read_image(path);
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot read '" + path.string() + "': No such file or directory");
  }
}

TEST(ImageWriterRead, RejectsTruncatedAndForeignFiles) {
  const fs::path dir = test::make_temp_dir("read-bad");
  write_image(distinct_image(), dir / "full.ppm");
  write_image(noise_image(16, 16), dir / "full.png");
  for (const char* name : {"full.ppm", "full.png"}) {
    const auto bytes = read_bytes(dir / name);
    ASSERT_GT(bytes.size(), 40u);
    const fs::path cut = dir / (std::string("cut-") + name);
    std::ofstream(cut, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                std::streamsize(bytes.size() - 20));
    EXPECT_THROW(read_image(cut), OutputError) << name;
  }
  std::ofstream(dir / "text.png") << "hello\n";
  std::ofstream(dir / "p3.ppm") << "P3\n1 1\n255\n0 0 0\n";
  std::ofstream(dir / "deep.ppm") << "P6\n1 1\n65535\n" << std::string(6, '\0');
  EXPECT_THROW(read_image(dir / "text.png"), OutputError);
  EXPECT_THROW(read_image(dir / "p3.ppm"), OutputError);
  EXPECT_THROW(read_image(dir / "deep.ppm"), OutputError);
}

TEST(ImageWriterRead, PpmHeaderCommentsAreSkipped) {
  const fs::path path = test::make_temp_dir("ppm-comment") / "c.ppm";
  std::ofstream(path, std::ios::binary) << "P6\n# made by hand\n2 1 # size\n255\n"
                                        << std::string("\x01\x02\x03\xfd\xfe\xff", 6);
  const Image image = read_image(path);
  ASSERT_EQ(image.width(), 2);
  ASSERT_EQ(image.height(), 1);
  EXPECT_EQ(image.at(0, 0), Color(code(1), code(2), code(3)));
  EXPECT_EQ(image.at(1, 0), Color(code(253), code(254), code(255)));
}

}  // namespace
}  // namespace mjray
