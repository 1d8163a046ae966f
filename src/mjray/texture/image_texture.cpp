#include "mjray/texture/image_texture.h"

#include <cmath>

namespace mjray {

namespace {

/// The two texels around continuous texel coordinate x on an axis of n texels (wrapped),
/// and the weight of the second.
struct Span {
  int first;
  int second;
  float weight;
};

Span span(double x, int n) {
  const double floored = std::floor(x);
  auto wrap = [n](double i) { return int(i - double(n) * std::floor(i / double(n))); };
  return {wrap(floored), wrap(floored + 1), float(x - floored)};
}

}  // namespace

Color ImageTexture::evaluate(const Point3&, const Point2& uv) const {
  const int w = image.width(), h = image.height();
  if (w <= 0 || h <= 0) return {};
  double u = uv.u, v = uv.v;
  if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
  // Repeat: only the fractional parts matter; then move to texel units, centres at +½.
  u -= std::floor(u);
  v -= std::floor(v);
  const Span x = span(u * w - 0.5, w);
  const Span y = span((1 - v) * h - 0.5, h);  // rows count down from the top
  const Color top = image.at(x.first, y.first) * (1 - x.weight) + image.at(x.second, y.first) * x.weight;
  const Color bottom = image.at(x.first, y.second) * (1 - x.weight) + image.at(x.second, y.second) * x.weight;
  return top * (1 - y.weight) + bottom * y.weight;
}

}  // namespace mjray
