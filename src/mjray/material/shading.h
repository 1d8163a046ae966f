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

  /// The same terms scaled down together where a channel of kd + ks exceeds 1, so that the
  /// surface reflects no more light than it receives.
  LocalShading energy_conserving() const {
    const float total = (kd + ks).max_component();
    return total > 1 ? LocalShading{kd / total, ks / total, shininess} : *this;
  }

  /// The density of `sample`'s directions at wi (solid angle).
  float pdf(const ShadingFrame& f, const Vector3& wi) const {
    const float cos_theta = dot(wi, f.n);
    if (cos_theta <= 0) return 0;
    constexpr float kInvPi = std::numbers::inv_pi_v<float>;
    const float cos_alpha = std::max(0.f, dot(reflect(f.wo, f.n), wi));
    const float glossy = (shininess + 1) * 0.5f * kInvPi * std::pow(cos_alpha, shininess);
    const float p = diffuse_share();
    return p * cos_theta * kInvPi + (1 - p) * glossy;
  }

  /// A direction drawn from the mixture of the two parts, chosen in proportion to their mean
  /// albedo: cos θ / π about n, or (s + 1)/2π · cos^s α about the mirror of wo. Returns its
  /// BRDF value and mixture density; nothing below the surface or when both parts are black.
  std::optional<BsdfSample> sample(const ShadingFrame& f, float u1, float u2) const {
    const float p = diffuse_share();
    if (!(p >= 0)) return std::nullopt;
    Vector3 wi;
    if (u1 < p) {
      wi = sample_cosine_hemisphere(Vector3(f.n), u1 / p, u2);
    } else {
      // Inverting the lobe's CDF gives cos α; a cone's rim (u1 = 1) is the direction at α.
      const float cos_alpha = std::pow(std::min((u1 - p) / (1 - p), 1.f), 1 / (shininess + 1));
      wi = sample_cone(reflect(f.wo, f.n), cos_alpha, 1, u2);
    }
    const float density = pdf(f, wi);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wi, eval(f, wi), density};
  }

 private:
  /// The chance `sample` draws from the diffuse part; NaN when both parts are black.
  float diffuse_share() const {
    const float d = kd.r + kd.g + kd.b, s = ks.r + ks.g + ks.b;
    return d / (d + s);
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
