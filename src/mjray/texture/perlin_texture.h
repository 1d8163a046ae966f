#pragma once
/// The five noise textures of the original project (gr.perlinnoise*texture): solid (3-D)
/// patterns built on Perlin's improved noise.

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Which function of the noise picks the blend between the two colours.
///
/// With q = scale · p (p the object-space point), n = perlin_noise, f = perlin_fractal with
/// kFractalOctaves octaves, T = perlin_turbulence with kTurbulenceOctaves octaves, and the
/// blend weight t ∈ [0, 1] (colour1 at 0, colour2 at 1):
/// - kLinear     t = clamp(½ + ½·f(q)), linear interpolation (Hugo Elias' octave sum)
/// - kCosine     the same t, cosine interpolation
/// - kMarble     t = 1 − |sin(π·(q.x + kMarbleTurbulence·T(q)))|, cosine interpolation
///               (Perlin's marble: veins of colour2, one per unit of q.x, bent by turbulence;
///               the |sin| cusp keeps them narrow on a colour1 ground)
/// - kWavy       t = ½ + ½·sin(2π·(q.x + noise_multiplier·n(q))), cosine interpolation
///               (smooth stripes; the multiplier is how many stripe periods the noise shifts)
/// - kWoodGrain  t = 20·n(q) − ⌊20·n(q)⌋, cosine interpolation (the report's §5.7 rings)
/// Cosine interpolation uses w = (1 − cos(π·t)) / 2 in place of t (Hugo Elias).
enum class PerlinPattern { kLinear, kCosine, kMarble, kWavy, kWoodGrain };

/// A noise texture. `scale` is a frequency: noise lattice cells per unit of the texture's
/// space, so a smaller scale makes the pattern larger ("scaled down in texture space").
struct PerlinTexture {
  static constexpr int kFractalOctaves = 4;       ///< octaves of f (kLinear, kCosine)
  static constexpr int kTurbulenceOctaves = 6;    ///< octaves of T (kMarble)
  static constexpr double kMarbleTurbulence = 1;  ///< vein periods the turbulence may shift
  static constexpr double kWoodRings = 20;        ///< rings per unit of noise (the report's 20)

  PerlinPattern pattern = PerlinPattern::kCosine;
  Color colour1;
  Color colour2;
  float scale = 1;             ///< noise cells per object unit, > 0
  float noise_multiplier = 1;  ///< kWavy only

  /// The blend weight t ∈ [0, 1] at an object-space point, before interpolation.
  double weight(const Point3& object_point) const;
  /// The colour at an object-space point (the uv is unused).
  Color evaluate(const Point3& object_point, const Point2& uv = {}) const;
};

}  // namespace mjray
