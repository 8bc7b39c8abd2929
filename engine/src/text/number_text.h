// Doubles as text: exact_text reads back to the same double (17 significant digits), for values handed
// on as key=value text (RunConfig::set); short_text is the 12 digits of the CSV files.
#pragma once
#include <cstdio>
#include <sstream>
#include <string>

namespace sph {

/// 12 significant digits, %g style: the CSV files' numbers (full precision for plots, short to read).
inline std::string short_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

inline std::string exact_text(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace sph
