#pragma once
/// The answers a material gives about a surface point: its local (non-specular) shading, the
/// specular directions that light arrives along, and what a shadow ray keeps crossing it.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "mjray/core/color.h"
#include "mjray/core/sampling.h"
#include "mjray/core/vector.h"
#include "mjray/material/optics.h"

namespace mjray {

/// The directions at a hit that every shading question is asked in. All unit, world space.
struct ShadingFrame {
  Vector3 wo;                ///< toward the viewer (away from the surface)
  Normal3 n;                 ///< shading normal, turned to wo's side
  Normal3 geometric_normal;  ///< as the surface is oriented: out of a closed object

  /// Whether wo is on the outside of the surface (the side the geometric normal points to).
  bool outside() const { return dot(wo, geometric_normal) > 0; }
};

/// A sampled direction of a BRDF: f(wo, wi) and the density it was drawn with (solid angle).
struct BsdfSample {
  Vector3 wi;
  Color f;
  float pdf = 0;
};

/// The CS 488 Phong terms at one hit (kd already read from the material's texture).
struct LocalShading {
  Color kd;             ///< diffuse reflectance
  Color ks;             ///< specular reflectance
  float shininess = 0;  ///< Phong exponent

  /// The ambient term: ambient light ⊙ kd.
  Color ambient(const Color& light) const { return light * kd; }

  /// CS 488 Phong reflection of a light in unit direction l with n·l > 0 (given), per unit
  /// of the light's intensity: kd·(n·l) + ks·max(0, r·wo)^shininess, r the mirror of l.
  Color phong(const ShadingFrame& f, const Vector3& l, float n_dot_l) const {
    const Vector3 r = Vector3(f.n) * (2 * n_dot_l) - l;
    const float r_dot_v = std::max(0.f, dot(r, f.wo));
    // ks·0 adds exactly nothing: skip the power where it cannot count.
    if (ks.is_black() || (r_dot_v == 0 && shininess > 0)) return kd * n_dot_l + Color{};
    return kd * n_dot_l + ks * std::pow(r_dot_v, shininess);
  }

  /// The physically based BRDF these terms map to, for transports beyond Whitted: kd as a
  /// Lambertian albedo and an energy-conserving Phong lobe (normalised by (s + 2) / 2π)
  /// around the mirror direction of wo. Zero below the surface.
  Color eval(const ShadingFrame& f, const Vector3& wi) const {
    if (dot(wi, f.n) <= 0) return {};
    constexpr float kInvPi = std::numbers::inv_pi_v<float>;
    const float cos_alpha = std::max(0.f, dot(reflect(f.wo, f.n), wi));
    return kd * kInvPi + ks * ((shininess + 2) * 0.5f * kInvPi * std::pow(cos_alpha, shininess));
  }

  /// A direction drawn with density cos θ / π about n, with its BRDF value; nothing when
  /// the draw lands on the horizon.
  std::optional<BsdfSample> sample(const ShadingFrame& f, float u1, float u2) const {
    const Vector3 wi = sample_cosine_hemisphere(Vector3(f.n), u1, u2);
    const float cos_theta = dot(wi, f.n);
    if (!(cos_theta > 0)) return std::nullopt;
    return BsdfSample{wi, eval(f, wi), cos_theta * std::numbers::inv_pi_v<float>};
  }
};

/// What a specular lobe sends light along: reflection or transmission (each has its own depth
/// limit, -r and -f).
enum class LobeKind { kReflection, kTransmission };

/// One direction light arrives from by specular reflection or refraction, with its weight in
/// the surface's colour. A glossy lobe (cos_cone < 1) spreads `samples` rays uniformly over the
/// cone of half-angle acos(cos_cone) around `direction` (one sample is one such ray); otherwise
/// the lobe is one ray along `direction` (a mirror or a lens).
struct SpecularLobe {
  Vector3 direction;
  float weight = 0;
  LobeKind kind = LobeKind::kReflection;
  float cos_cone = 1;
  int samples = 1;
};

/// The specular lobes of one hit: at most a reflection and a transmission; no allocation.
class SpecularLobes {
 public:
  static constexpr int kCapacity = 2;

  /// Adds a lobe when its weight is positive (a zero-weight lobe would trace for nothing).
  void add(const SpecularLobe& lobe) {
    if (lobe.weight > 0 && count_ < kCapacity) lobes_[size_t(count_++)] = lobe;
  }
  const SpecularLobe* begin() const { return lobes_.data(); }
  const SpecularLobe* end() const { return lobes_.data() + count_; }
  bool empty() const { return count_ == 0; }

 private:
  std::array<SpecularLobe, kCapacity> lobes_{};
  int count_ = 0;
};

}  // namespace mjray
