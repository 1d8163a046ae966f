#include "mjray/render/image_sampler.h"

namespace mjray {

void ImageSampler::first_pass(const PixelRect& rect, Film& film, TraceState& state) const {
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      RandomStream random(settings_.seed, pixel_key(x, y), first_pass_sample_index(0));
      film.add(x, y, integrator_.radiance(camera_.generate_ray(float(x) + 0.5f, float(y) + 0.5f), random, state));
    }
}

FilmPixel ImageSampler::supersample(int x, int y, TraceState& state) const {
  // Compute the sum over an N×N jittered grid of the pixel.
  const int n = settings_.antialias_samples;
  Color sum;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RandomStream random(settings_.seed, pixel_key(x, y), antialias_sample_index(uint32_t(j * n + i)));
      const float sx = float(x) + (float(i) + random.uniform()) / float(n);
      const float sy = float(y) + (float(j) + random.uniform()) / float(n);
      sum += integrator_.radiance(camera_.generate_ray(sx, sy), random, state);
    }
  return {sum, float(n * n)};
}

}  // namespace mjray
