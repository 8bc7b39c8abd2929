// Doubles as text: exact_text reads back to the same double (the fewest digits that do), for values handed
// on as key=value text (RunConfig::set) and shown in messages; short_text is the 12 digits of the CSV files;
// g_text any other count of %g digits.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace sph {

/// `digits` significant digits, %g style (6: plain %g).
inline std::string g_text(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// 12 significant digits, %g style: the CSV files' numbers (full precision for plots, short to read).
inline std::string short_text(double v) { return g_text(v, 12); }

/// The shortest %g text that reads back to the same double (0.1, not 0.10000000000000001; 100, not
/// 1e+02, between 1e-4 and 1e15): exact for key=value text, short for messages and help.
inline std::string exact_text(double v) {
  char buf[40];
  const double a = v < 0.0 ? -v : v;
  const bool fixed = a >= 1e-4 && a < 1e15;  // where %g can write it without an exponent
  for (int digits = 1; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v && !(fixed && std::string_view(buf).find('e') != std::string_view::npos))
      return buf;
  }
  return g_text(v, 17);  // 17 digits always read back (and NaN, inf print as such)
}

}  // namespace sph
