// The mapping of a logarithmic slider (cfl, visc.eps, h.tol ...): the slider moves u = log10(v) between
// log10(min) and log10(max). Pure functions, so the mapping is tested without a window.
#pragma once
#include <algorithm>
#include <cmath>

namespace sph::gui {

/// Slider position of value v (clamped into [min, max]; min > 0).
inline double log_position(double v, double min, double max) {
  return std::log10(std::clamp(v, min, max));
}

/// Value at slider position u: 10^u, snapped to the exact ends (10^log10(2) is 2.0000000000000004,
/// which the range check rejects) and clamped into [min, max].
inline double log_value(double u, double min, double max) {
  const double lo = std::log10(min), hi = std::log10(max);
  if (u <= lo) return min;
  if (u >= hi) return max;
  return std::clamp(std::pow(10.0, u), min, max);
}

}  // namespace sph::gui
