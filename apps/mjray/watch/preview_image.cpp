#include "preview_image.h"

#include "mjray/core/error.h"

namespace mjray {

Image enlarge(const Image& coarse, int width, int height) {
  MJRAY_CHECK(coarse.width() > 0 && coarse.height() > 0);
  Image out(width, height);
  for (int y = 0; y < height; ++y) {
    const int cy = int(int64_t(y) * coarse.height() / height);
    for (int x = 0; x < width; ++x) out.at(x, y) = coarse.at(int(int64_t(x) * coarse.width() / width), cy);
  }
  return out;
}

Image overlay_finished_tiles(const Image& underlay, const Image& snapshot, const std::vector<uint8_t>& finished,
                             const TileLayout& layout) {
  MJRAY_CHECK(finished.size() == size_t(layout.count()));
  MJRAY_CHECK(underlay.width() == layout.width && snapshot.width() == layout.width);
  MJRAY_CHECK(underlay.height() == layout.height && snapshot.height() == layout.height);
  Image out = underlay;
  for (int t = 0; t < layout.count(); ++t) {
    if (!finished[size_t(t)]) continue;
    const PixelRect r = layout.rect(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) out.at(x, y) = snapshot.at(x, y);
  }
  return out;
}

}  // namespace mjray
