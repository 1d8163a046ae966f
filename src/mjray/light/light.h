#pragma once
/// The closed set of lights.
///
/// To add a light: write `<name>_light.h`, add it to `Light`, teach the integrator's
/// `direct_light` how to sample it (light_samples), and bind it in `lua/gr_bindings.cpp`.

#include <variant>

#include "mjray/light/area_light.h"
#include "mjray/light/point_light.h"

namespace mjray {

using Light = std::variant<PointLight, AreaLight>;

}  // namespace mjray
