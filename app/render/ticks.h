// Axis ticks at "nice" round numbers (1, 2, 5 x 10^k) and the number formats of labels.
#pragma once
#include <string>
#include <vector>

namespace sph::render {

struct Ticks {
  std::vector<double> values;  ///< tick positions inside [lo, hi], increasing
  double step = 1.0;           ///< spacing between ticks
};

/// About `target` ticks (at least 2 when possible) covering [lo, hi].
Ticks nice_ticks(double lo, double hi, int target);
/// [lo, hi] widened outwards to multiples of a nice step (axis limits of a profile plot).
void nice_limits(double& lo, double& hi, int target);
/// A tick label: as many decimals as the step needs; scientific notation for very large/small values.
std::string format_tick(double v, double step);
/// A value with 4 significant digits ("0.2500", "1.234e+05"): colour-bar ends.
std::string format_value(double v);

}  // namespace sph::render
