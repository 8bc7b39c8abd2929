// Names of the 2D profile view's axis (ViewSettings::profile_axis) for flags and menus:
// "off" (-1, the plane view), "x" (0), "y" (1).
#pragma once
#include <optional>
#include <string_view>

namespace sph::render {

/// -1, 0 or 1 for "off", "x", "y"; nullopt for anything else.
inline std::optional<int> parse_profile_axis(std::string_view name) {
  if (name == "off") return -1;
  if (name == "x") return 0;
  if (name == "y") return 1;
  return std::nullopt;
}

/// The coordinate's name ("x", "y", "z") for axis 0..2, else "off".
inline std::string_view profile_axis_name(int axis) {
  constexpr std::string_view kNames[3] = {"x", "y", "z"};
  return axis >= 0 && axis < 3 ? kNames[axis] : std::string_view("off");
}

}  // namespace sph::render
