// The diagnostics panel's text: values that never run wider than the column measured for them, and
// plot titles that give the value of the frame on screen (a diverged run says so, rather than showing
// the last sample taken before it blew up).
#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sph/stepper.h"

namespace sph::gui {

/// v with `digits` significant digits ("%.*g"; "inf", "-inf"; a dash, never "nan", for a value not defined).
std::string value_text(double v, int digits = 6);

/// "E_tot = 1.2345", plus "  (diverged at step 812)" when the frame diverged.
std::string plot_title(std::string_view name, double now, const StepperFrame& f);

/// A row of the numbers table: name, value text, tooltip.
struct DiagRow {
  std::string name, value, tip;
};

/// The "dE/E0" row: E_tot's relative change since t = 0, or a dash where the scene's method does not
/// conserve energy (SceneSpec::energy_bound = 0: the finite pointset method, walls or damping doing work,
/// viscosity without an energy equation), where a number would read as the method's error.
DiagRow energy_change_row(double dE, bool conserved);

/// Widths [px] of the name and value columns that hold every row, `measure` giving a text's width.
struct DiagWidths {
  float name = 0.f, value = 0.f;
};
DiagWidths diag_widths(const std::vector<DiagRow>& rows, const std::function<float(const std::string&)>& measure);

}  // namespace sph::gui
