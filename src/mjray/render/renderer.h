#pragma once
/// Renders an image over tiles on all cores; every pixel is independent of thread and order.

#include <cstdint>
#include <functional>

#include "mjray/camera/pinhole_camera.h"
#include "mjray/core/image.h"
#include "mjray/integrator/whitted_integrator.h"

namespace mjray {

/// How to schedule the work.
struct RenderSettings {
  int threads = 0;     ///< 0 = all cores
  int tile_size = 16;  ///< pixels per tile side
  uint64_t seed = 0;   ///< --seed: keys every random number
  int antialias_samples = 0;        ///< -a: N×N jittered samples in bad pixels; 0 = off
  float antialias_threshold = 0.1f; ///< --aa-threshold: neighbour difference that makes a pixel bad
  int antialias_max_passes = 4;     ///< passes of adaptive supersampling at most
};

/// What the render did.
struct RenderStats {
  RayCounters rays;
  double seconds = 0;
  int threads = 1;
  uint64_t pixels_supersampled = 0;
  int antialias_passes = 0;
};

/// Renders width × height pixels with one primary ray through each pixel centre, then, when
/// asked, supersamples the pixels adaptive anti-aliasing finds bad.
Image render_image(const PinholeCamera& camera, int width, int height,
                   const WhittedIntegrator& integrator, const RenderSettings& settings,
                   RenderStats* stats = nullptr);

/// The number of worker threads `requested` means on this machine (0 = all cores).
int resolve_thread_count(int requested);

}  // namespace mjray
