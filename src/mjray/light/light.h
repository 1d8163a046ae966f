#pragma once
/// The closed set of lights and the questions every one of them answers.
///
/// Each light is a struct in `<name>_light.h` with
///   - `int samples_per_axis(int requested)`: how many samples along each axis of the -s
///     grid it needs (1 for a point);
///   - `LightSample sample_li(receiver, u)`: the point at u ∈ [0,1)², the light from it and
///     its distance from the receiver;
///   - `std::array<Point3, 4> sample_region()`: the parallelogram all those points lie in;
///   - `EmittedRay sample_le(u_position, u_direction)`, `EmissionPoint emission_point(u)` and
///     `Color power()`: emission, for transports that start at lights;
///   - `float attenuation(float d)`: the falloff 1 / (c0 + c1·d + c2·d²) at distance d.
/// The functions below dispatch with std::visit, so a light missing one does not compile.
/// To add a light: write the struct, add it to `Light`, bind it in `lua/gr_bindings.cpp` or
/// `lua/extension_bindings.cpp`, and test it in `tests/unit/light/`.

#include <variant>

#include "mjray/light/area_light.h"
#include "mjray/light/point_light.h"

namespace mjray {

using Light = std::variant<PointLight, AreaLight>;

inline int samples_per_axis(const Light& light, int requested) {
  return std::visit([&](const auto& l) { return l.samples_per_axis(requested); }, light);
}
inline LightSample sample_li(const Light& light, const Point3& receiver, Point2 u) {
  return std::visit([&](const auto& l) { return l.sample_li(receiver, u); }, light);
}
inline std::array<Point3, 4> sample_region(const Light& light) {
  return std::visit([](const auto& l) { return l.sample_region(); }, light);
}
inline EmittedRay sample_le(const Light& light, Point2 u_position, Point2 u_direction) {
  return std::visit([&](const auto& l) { return l.sample_le(u_position, u_direction); }, light);
}
inline EmissionPoint emission_point(const Light& light, Point2 u) {
  return std::visit([&](const auto& l) { return l.emission_point(u); }, light);
}
inline float attenuation(const Light& light, float d) {
  return std::visit([&](const auto& l) { return l.attenuation(d); }, light);
}
inline Color power(const Light& light) {
  return std::visit([](const auto& l) { return l.power(); }, light);
}

}  // namespace mjray
