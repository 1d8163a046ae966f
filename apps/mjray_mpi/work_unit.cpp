#include "work_unit.h"

#include <utility>

#include "mjray/core/error.h"

namespace mjray {

std::optional<std::vector<FilmPixel>> render_unit(const ImageSampler& sampler, const TileLayout& layout,
                                                  const WorkUnit& unit, Film& scratch, TraceState& state,
                                                  std::stop_token stop) {
  std::vector<FilmPixel> values;
  if (unit.kind == WorkUnit::Kind::kPixels) {
    values.reserve(unit.pixels.size());
    for (const int32_t p : unit.pixels) {
      if (stop.stop_requested()) return std::nullopt;
      values.push_back(sampler.sample_pixel(p % sampler.width(), p / sampler.width(), unit.pass, state));
    }
    return values;
  }
  // The first pass adds to the film, so the rectangle starts empty and is emptied again (an
  // abandoned one is left as it is: its pool is going away).
  const PixelRect r = layout.rect(unit.id);
  if (!sampler.first_pass(r, scratch, state, stop)) return std::nullopt;
  values.reserve(size_t(r.pixel_count()));
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) values.push_back(std::exchange(scratch.at(x, y), FilmPixel{}));
  return values;
}

void store_tile(const TileLayout& layout, int tile, const std::vector<FilmPixel>& values, Film& film) {
  const PixelRect r = layout.rect(tile);
  MJRAY_CHECK(values.size() == size_t(r.pixel_count()));
  size_t k = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) film.at(x, y) = values[k++];
}

}  // namespace mjray
