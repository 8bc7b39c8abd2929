#include "diag_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sph::gui {

std::string value_text(double v, int digits) {
  if (std::isnan(v)) return "\u2014";  // not defined (yet): e.g. a reference before its quantity exists
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string plot_title(std::string_view name, double now, const StepperFrame& f) {
  std::string t = std::string(name) + " = " + value_text(now);
  if (f.diverged) t += "  (diverged at step " + std::to_string(f.diverged_step) + ")";
  return t;
}

DiagWidths diag_widths(const std::vector<DiagRow>& rows, const std::function<float(const std::string&)>& measure) {
  DiagWidths w;
  for (const DiagRow& r : rows) {
    w.name = std::max(w.name, measure(r.name));
    w.value = std::max(w.value, measure(r.value));
  }
  return w;
}

DiagRow energy_change_row(double dE, bool conserved) {
  if (conserved) return {"dE/E0", value_text(dE, 3), "relative change of E_tot since t = 0"};
  return {"dE/E0", value_text(std::nan(""), 3),
          "not shown: this scene's method does not conserve energy (the finite pointset method, walls or damping "
          "doing work, viscosity without an energy equation); E_tot and its curve show how it changes"};
}

}  // namespace sph::gui
