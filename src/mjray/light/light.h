#pragma once
/// The closed set of lights and the questions every one of them answers.
///
/// Each light is a struct in `<name>_light.h` with
///   - `int samples_per_axis(int requested)`: how many samples along each axis of the -s
///     grid it needs (1 for a point);
///   - `LightSample sample_li(receiver, u)`: the point at u ∈ [0,1)², the light from it and
///     its distance from the receiver;
///   - `std::array<Point3, 4> sample_region(receiver)`: the parallelogram all those points lie in;
///   - `Color power()`: its flux, for choosing among lights;
///   - `float photon_falloff(d)`: what a photon's flux is multiplied by after its first flight
///     of length d (the light's falloff in place of the 1 / d² its spread already gives);
/// and, for lights at a position (all but the sun, whose photons leave a disc beyond the
/// scene: integrator/photon/photon_emission.cpp):
///   - `EmissionPoint emission_point(u)`: a point photons leave from, and its intensity;
///   - `float emission_profile(w)`, `EmissionCone emission_cone()`: the share of that intensity
///     sent along w, and the cone outside which it is 0.
/// The functions below dispatch with std::visit, so a light missing one does not compile.
/// To add a light: write the struct, add it to `Light`, bind it in `lua/gr_bindings.cpp` or
/// `lua/extension_bindings.cpp`, and test it in `tests/unit/light/`.

#include <variant>

#include "mjray/core/error.h"
#include "mjray/light/area_light.h"
#include "mjray/light/point_light.h"
#include "mjray/light/spot_light.h"
#include "mjray/light/sun_light.h"

namespace mjray {

using Light = std::variant<PointLight, AreaLight, SpotLight, SunLight>;

inline int samples_per_axis(const Light& light, int requested) {
  return std::visit([&](const auto& l) { return l.samples_per_axis(requested); }, light);
}
inline LightSample sample_li(const Light& light, const Point3& receiver, Point2 u) {
  return std::visit([&](const auto& l) { return l.sample_li(receiver, u); }, light);
}
inline std::array<Point3, 4> sample_region(const Light& light, const Point3& receiver) {
  return std::visit([&](const auto& l) { return l.sample_region(receiver); }, light);
}
inline Color power(const Light& light) {
  return std::visit([](const auto& l) { return l.power(); }, light);
}
inline float photon_falloff(const Light& light, float d) {
  return std::visit([&](const auto& l) { return l.photon_falloff(d); }, light);
}

/// The sun, when `light` is one: a light without a position.
inline const SunLight* distant_light(const Light& light) { return std::get_if<SunLight>(&light); }

/// A light with a position's answers (see above); not to be asked of a distant light.
template <typename Question>
auto ask_local_light(const Light& light, Question question) {
  return std::visit(
      [&](const auto& l) {
        if constexpr (std::is_same_v<std::decay_t<decltype(l)>, SunLight>) {
          MJRAY_CHECK(!"a distant light has no position");
          return question(PointLight{});
        } else {
          return question(l);
        }
      },
      light);
}
inline EmissionPoint emission_point(const Light& light, Point2 u) {
  return ask_local_light(light, [&](const auto& l) { return l.emission_point(u); });
}
inline float emission_profile(const Light& light, const Vector3& w) {
  return ask_local_light(light, [&](const auto& l) { return l.emission_profile(w); });
}
inline EmissionCone emission_cone(const Light& light) {
  return ask_local_light(light, [](const auto& l) { return l.emission_cone(); });
}

}  // namespace mjray
