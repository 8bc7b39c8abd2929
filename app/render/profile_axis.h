// Names of the profile view's axis (ViewSettings::profile_axis) for flags and menus: "off" (-1, the
// plane or 3D view), "x" (0), "y" (1) for 2D scenes, "r" (3, the distance from the origin) for 2D and 3D.
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>

#include "sph/snapshot.h"

namespace sph::render {

inline constexpr int kRadialAxis = 3;  ///< profile against r = |x| (the spheres of the gravity scenes)

/// -1, 0, 1 or 3 for "off", "x", "y", "r"; nullopt for anything else.
inline std::optional<int> parse_profile_axis(std::string_view name) {
  if (name == "off") return -1;
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "r") return kRadialAxis;
  return std::nullopt;
}

/// The coordinate's name ("x", "y", "z", "r") for axis 0..3, else "off".
inline std::string_view profile_axis_name(int axis) {
  constexpr std::string_view kNames[4] = {"x", "y", "z", "r"};
  return axis >= 0 && axis < 4 ? kNames[axis] : std::string_view("off");
}

/// Particle i's coordinate along `axis` (0..2; kRadialAxis: its distance from the origin): where a profile
/// draws it. Missing coordinates count as 0.
inline float profile_coordinate(const sph::Snapshot& snap, std::size_t i, int axis) {
  const auto at = [&](const std::vector<float>& v) { return i < v.size() ? v[i] : 0.f; };
  if (axis == kRadialAxis) {
    const float x = at(snap.x), y = at(snap.y), z = at(snap.z);
    return std::sqrt(x * x + y * y + z * z);
  }
  return at(axis == 1 ? snap.y : axis == 2 ? snap.z : snap.x);
}

/// Whether a scene of dimension dim is drawn as a profile along `axis` (1D scenes always are, along x).
inline bool draws_profile(int dim, int axis) {
  return dim == 1 || (dim == 2 && (axis == 0 || axis == 1)) || (dim >= 2 && axis == kRadialAxis);
}

}  // namespace sph::render
