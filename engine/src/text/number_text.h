// Doubles as text: exact_text reads back to the same double (17 significant digits), for values handed
// on as key=value text (RunConfig::set); short_text is the 12 digits of the CSV files;
// g_text any other count of %g digits.
#pragma once
#include <cstdio>
#include <sstream>
#include <string>

namespace sph {

/// `digits` significant digits, %g style (6: plain %g).
inline std::string g_text(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// 12 significant digits, %g style: the CSV files' numbers (full precision for plots, short to read).
inline std::string short_text(double v) { return g_text(v, 12); }

inline std::string exact_text(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace sph
