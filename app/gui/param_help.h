// The text of the parameter tooltips that says what a value is measured in: every run parameter and
// every scene value gives its unit (or "dimensionless"). Pure functions, tested without a window.
#pragma once
#include <string>

#include "sph/param_table.h"
#include "sph/scene.h"

namespace sph::gui {

/// "unit: length/time    range: [1e-09, 1e+09]" (choices: "one of: M4 M5 ...").
std::string param_unit_line(const ParamInfo& info);

/// The whole tooltip of a scene value: key, description, unit, range, and that it needs a reset.
std::string scene_value_help(const SceneParam& sp);

}  // namespace sph::gui
