// One "  name = value" item of the summary lines of `sph run`: 6 significant digits, and "—" for a value
// the reference does not define (NaN: e.g. Sod's rho_min, which only a tube with a vacuum region has).
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace sph::cli {

inline std::string summary_item(const std::string& name, double v) {
  if (std::isnan(v)) return "  " + name + " = —";
  char item[96];
  std::snprintf(item, sizeof item, "  %s = %.6g", name.c_str(), v);
  return item;
}

}  // namespace sph::cli
