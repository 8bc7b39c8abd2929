// The diagnostics panel's text (app/gui/diag_text.h): the value column is as wide as its widest value
// (E_kin = -1.23457e-05 ran into the plot column), and plot titles follow the frame on screen.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "diag_text.h"

namespace sph::gui {
namespace {

float eight_px_per_char(const std::string& s) { return 8.f * static_cast<float>(s.size()); }

TEST(DiagText, ColumnsHoldTheWidestValue) {
  const std::vector<DiagRow> rows = {{"E_kin", value_text(-1.2345678e-305), ""},
                                     {"E_tot", value_text(12.5), ""},
                                     {"Linf_rho_long_name", value_text(0.25), ""}};
  const DiagWidths w = diag_widths(rows, eight_px_per_char);
  EXPECT_EQ(rows[0].value, "-1.23457e-305");
  EXPECT_EQ(w.value, 8.f * 13.f);
  EXPECT_EQ(w.name, 8.f * 18.f);
  for (const DiagRow& r : rows) {
    EXPECT_LE(eight_px_per_char(r.value), w.value);
    EXPECT_LE(eight_px_per_char(r.name), w.name);
  }
}

TEST(DiagText, NonFiniteValuesAreNamed) {
  EXPECT_EQ(value_text(std::nan("")), "\u2014");  // a dash: a student never reads "nan" as a value
  EXPECT_EQ(value_text(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(value_text(0.1234567891, 4), "0.1235");
}

TEST(DiagText, EnergyChangeIsADashWhereTheMethodDoesNotConserveEnergy) {
  // Burgers by FPM showed "dE/E0 = 0.779" as if it were the method's error
  EXPECT_EQ(energy_change_row(0.779, false).value, "\u2014");
  EXPECT_NE(energy_change_row(0.779, false).tip.find("does not conserve energy"), std::string::npos);
  EXPECT_EQ(energy_change_row(-3.2e-4, true).value, "-0.00032");
  EXPECT_EQ(energy_change_row(0.779, true).name, "dE/E0");
}

TEST(DiagText, TitlesGiveTheFrameValueAndTheDivergence) {
  StepperFrame f;
  EXPECT_EQ(plot_title("E_tot", 2.5, f), "E_tot = 2.5");
  f.diverged = true;
  f.diverged_step = 812;
  EXPECT_EQ(plot_title("E_tot", std::nan(""), f), "E_tot = \u2014  (diverged at step 812)");
}

}  // namespace
}  // namespace sph::gui
