#include "ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sph::render {

namespace {

// The 1, 2, 5 x 10^k nearest to raw (geometrically).
double nice_step(double raw) {
  if (!(raw > 0.0) || !std::isfinite(raw)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / p;  // in [1, 10)
  const double nice = m < 1.4142 ? 1.0 : m < 3.1623 ? 2.0 : m < 7.0711 ? 5.0 : 10.0;
  return nice * p;
}

std::string printf_string(const char* fmt, int digits, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, digits, v);
  return buf;
}

}  // namespace

Ticks nice_ticks(double lo, double hi, int target) {
  Ticks t;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return t;
  t.step = nice_step((hi - lo) / std::max(target, 1));
  const double first = std::ceil(lo / t.step - 1e-9) * t.step;
  for (int k = 0; k < 1000; ++k) {
    const double v = first + k * t.step;
    if (v > hi + 1e-9 * t.step) break;
    t.values.push_back(std::abs(v) < 1e-12 * t.step ? 0.0 : v);  // no "-0"
  }
  return t;
}

void nice_limits(double& lo, double& hi, int target) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return;
  const double step = nice_step((hi - lo) / std::max(target, 1));
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
}

std::string format_tick(double v, double step) {
  const double mag = std::max(std::abs(v), step);
  if (mag >= 1e5 || (step < 1e-4 && mag < 1e-3)) return printf_string("%.*e", 1, v);
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 8);
  std::string s = printf_string("%.*f", decimals, v);
  if (s == "-0" || s.find_first_not_of("-0.") == std::string::npos) s = printf_string("%.*f", decimals, 0.0);
  return s;
}

std::string format_value(double v) {
  if (v == 0.0) return "0";
  const double a = std::abs(v);
  if (a >= 1e5 || a < 1e-3) return printf_string("%.*e", 3, v);
  // 4 significant digits in fixed notation.
  const int decimals = std::clamp(3 - static_cast<int>(std::floor(std::log10(a))), 0, 6);
  return printf_string("%.*f", decimals, v);
}

}  // namespace sph::render
