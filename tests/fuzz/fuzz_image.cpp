// libFuzzer target: image bytes (PNG, JPEG, PPM, chosen by their magic) through read_image,
// as gr.filetexture and --resume read them. A corrupt file must end in an OutputError; a crash,
// a sanitizer report, another exception or an image whose size disagrees with its pixels is a
// finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "mjray/core/error.h"
#include "mjray/io/image_reader.h"

namespace {

/// A private file the input is written to (read_image reads files); removed at exit. Never
/// destroyed, so that the exit handler can still use it.
const std::filesystem::path& input_path() {
  static const std::filesystem::path* path = [] {
    std::string folder = (std::filesystem::temp_directory_path() / "mjray-fuzz-image-XXXXXX").string();
    if (::mkdtemp(folder.data()) == nullptr) std::abort();
    auto* file = new std::filesystem::path(std::filesystem::path(folder) / "input");
    std::atexit([] { std::filesystem::remove_all(input_path().parent_path()); });
    return file;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& path = input_path();
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) std::abort();
  try {
    const mjray::Image image = mjray::read_image(path);
    if (image.width() <= 0 || image.height() <= 0 ||
        image.pixels().size() != size_t(image.width()) * size_t(image.height()))
      std::abort();
    for (const mjray::Color& c : image.pixels())
      if (!(c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1)) std::abort();
  } catch (const mjray::OutputError&) {
  }
  return 0;
}
