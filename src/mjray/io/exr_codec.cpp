#include "mjray/io/exr_codec.h"

#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include <cstring>
#include <ctime>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/io/image_reader.h"

namespace mjray {

namespace {

/// An OpenEXR output stream into memory, so that the file is written atomically by its caller.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (n <= 0) return;
    if (position_ + size_t(n) > bytes_.size()) bytes_.resize(position_ + size_t(n));
    std::memcpy(bytes_.data() + position_, c, size_t(n));
    position_ += size_t(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = position; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
  size_t position_ = 0;
};

/// Now as EXR's capDate wants it: "YYYY:MM:DD hh:mm:ss", local time.
std::string capture_date() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
  return text;
}

[[noreturn]] void fail_read(const std::filesystem::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

}  // namespace

bool has_exr_magic(const unsigned char* bytes, size_t size) {
  return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

std::string encode_exr(const Image& image, const EncodeOptions& options) {
  const int width = image.width(), height = image.height();
  std::vector<half> rgb(size_t(width) * size_t(height) * 3);
  for (size_t i = 0; i < image.pixels().size(); ++i) {
    const Color& c = image.pixels()[i];
    rgb[3 * i] = half(c.r);
    rgb[3 * i + 1] = half(c.g);
    rgb[3 * i + 2] = half(c.b);
  }
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::HALF));
    for (const auto& [key, value] : options.metadata) header.insert(key, Imf::StringAttribute(value));
    if (options.render_seconds) header.insert("renderSeconds", Imf::FloatAttribute(float(*options.render_seconds)));
    Imf::addCapDate(header, capture_date());
    Imf::FrameBuffer frame;
    const size_t pixel = 3 * sizeof(half), row = pixel * size_t(width);
    frame.insert("R", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgb.data()), pixel, row));
    frame.insert("G", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgb.data() + 1), pixel, row));
    frame.insert("B", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgb.data() + 2), pixel, row));
    MemoryStream stream;
    {
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame);
      file.writePixels(height);
    }
    return stream.take();
  } catch (const std::exception& e) {
    throw OutputError(std::string("OpenEXR: ") + e.what());
  }
}

Image decode_exr(const std::filesystem::path& path, size_t max_pixels) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int64_t width = int64_t(window.max.x) - window.min.x + 1, height = int64_t(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0) fail_read(path, "bad EXR size " + std::to_string(width) + "x" + std::to_string(height));
    check_image_size(path, uint64_t(width), uint64_t(height), max_pixels);
    const Imf::ChannelList& channels = file.header().channels();
    const bool grey = !channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B");
    if (grey && !channels.findChannel("Y")) fail_read(path, "the EXR has no R, G, B or Y channel");
    Image image{int(width), int(height)};
    const size_t pixel = sizeof(Color), row = pixel * size_t(width);
    char* base = reinterpret_cast<char*>(image.data());
    Imf::FrameBuffer frame;
    if (grey) {
      frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, base, window, pixel, row));
    } else {
      frame.insert("R", Imf::Slice::Make(Imf::FLOAT, base, window, pixel, row));
      frame.insert("G", Imf::Slice::Make(Imf::FLOAT, base + sizeof(float), window, pixel, row));
      frame.insert("B", Imf::Slice::Make(Imf::FLOAT, base + 2 * sizeof(float), window, pixel, row));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (grey)
      for (size_t i = 0; i < image.pixels().size(); ++i) image.data()[i].g = image.data()[i].b = image.data()[i].r;
    return image;
  } catch (const OutputError&) {
    throw;
  } catch (const std::exception& e) {
    fail_read(path, std::string("OpenEXR: ") + e.what());
  }
}

ImageMetadata decode_exr_metadata(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    ImageMetadata text;
    for (auto it = file.header().begin(); it != file.header().end(); ++it)
      if (const auto* value = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        text.emplace_back(it.name(), value->value());
    return text;
  } catch (const std::exception& e) {
    fail_read(path, std::string("OpenEXR: ") + e.what());
  }
}

}  // namespace mjray
