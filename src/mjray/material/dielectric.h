#pragma once
/// What refractive materials share: the reflected and transmitted lobes at a boundary between
/// two indices of refraction, and the light a shadow ray keeps crossing it.

#include <algorithm>
#include <cmath>

#include "mjray/material/optics.h"
#include "mjray/material/shading.h"

namespace mjray {

/// The indices on either side of the boundary as `f.wo` crosses it: entering or leaving is
/// decided by the geometric normal, which points out of the object.
struct BoundaryIndices {
  float eta_i;  ///< on wo's side
  float eta_t;  ///< on the far side
};
inline BoundaryIndices boundary_indices(const ShadingFrame& f, float eta_outside, float eta_inside) {
  return f.outside() ? BoundaryIndices{eta_outside, eta_inside} : BoundaryIndices{eta_inside, eta_outside};
}

/// Kr · reflected + (1 − Kr) · refracted; `kr_of(cos_i, eta_i, eta_t)` gives Kr (a constant,
/// or Fresnel). Under total internal reflection everything reflects.
template <class Reflectance>
SpecularLobes dielectric_lobes(const ShadingFrame& f, float eta_outside, float eta_inside, Reflectance kr_of) {
  const auto [eta_i, eta_t] = boundary_indices(f, eta_outside, eta_inside);
  float kr = kr_of(dot(f.wo, f.n), eta_i, eta_t);
  const auto transmitted = refract(f.wo, f.n, eta_i / eta_t);
  if (!transmitted) kr = 1;
  SpecularLobes lobes;
  lobes.add({reflect(f.wo, f.n), kr, LobeKind::kReflection});
  if (transmitted) lobes.add({*transmitted, 1 - kr, LobeKind::kTransmission});
  return lobes;
}

/// The share a straight shadow ray keeps crossing the boundary (f.wo points back along the
/// shadow ray): the weight 1 − Kr the refracted ray gets there, as seen from outside at the
/// ray's angle θ, on the way in and on the way out alike. Shadow rays do not bend, so the
/// angle inside is the angle outside; by reciprocity a slab then passes (1 − Kr(θ))², and
/// no crossing is total internal reflection.
template <class Reflectance>
float dielectric_transmittance(const ShadingFrame& f, float eta_outside, float eta_inside, Reflectance kr_of) {
  return std::clamp(1 - kr_of(std::abs(dot(f.wo, f.n)), eta_outside, eta_inside), 0.f, 1.f);
}

}  // namespace mjray
