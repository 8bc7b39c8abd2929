// How the help texts (sph/help_text.h) lay out values: padded columns, %g numbers, parameter values in
// their shortest exact form, units and ranges. Shared by params/help_text.cpp and world/scene_help.cpp.
#pragma once
#include <string>
#include <string_view>

#include "sph/param_table.h"

namespace sph::help_format {

/// s padded with spaces to `width` columns (never cut).
std::string pad(std::string s, std::size_t width);
/// %g.
std::string number(double v);
/// A parameter's value as text: numbers in their shortest exact form (0.3, not 0.29999999999999999).
std::string shown(const std::string& value);
/// The unit, "dimensionless" when there is none.
std::string unit_of(std::string_view unit);
/// "unit length/time, range [0, 10]" or "one of M4 M5 ..." for one run parameter.
std::string value_space(const ParamInfo& info);

}  // namespace sph::help_format
