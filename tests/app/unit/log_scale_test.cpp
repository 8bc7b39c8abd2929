// The logarithmic slider's mapping (app/gui/log_scale.h): the ends give the range's exact ends (the
// right end of cfl gave 2.0000000000000004, "out of range"), positions round-trip, values outside the
// range clamp. Typed values no longer pass through it (the slider's Ctrl+click input is off).
#include <gtest/gtest.h>

#include <cmath>

#include "log_scale.h"

namespace sph::gui {
namespace {

TEST(LogScale, EndsAreTheExactRangeEnds) {
  const double ranges[][2] = {{0.01, 2.0}, {1e-15, 1e-2}, {1e-4, 1.0}, {0.003, 7.0}};
  for (const auto& r : ranges) {
    EXPECT_EQ(log_value(std::log10(r[1]), r[0], r[1]), r[1]);
    EXPECT_EQ(log_value(std::log10(r[0]), r[0], r[1]), r[0]);
    EXPECT_EQ(log_value(std::log10(r[1]) + 1e-9, r[0], r[1]), r[1]);
  }
  // positions a slider can produce next to the right end never give a value above the range
  for (int k = 0; k < 1000; ++k) {
    const double u = std::nextafter(std::log10(2.0), 0.0) - k * 1e-16;
    EXPECT_LE(log_value(u, 0.01, 2.0), 2.0) << k;
  }
}

TEST(LogScale, PositionsRoundTripAndClamp) {
  for (double v : {0.3, 0.5, 0.01, 1.0, 1.7}) {
    const double back = log_value(log_position(v, 0.01, 2.0), 0.01, 2.0);
    EXPECT_NEAR(back, v, 1e-15 * v) << v;  // 0.3 stays 0.3 (it became 2 when read as log10)
  }
  EXPECT_EQ(log_position(5.0, 0.01, 2.0), std::log10(2.0));
  EXPECT_EQ(log_position(0.0, 0.01, 2.0), std::log10(0.01));
}

}  // namespace
}  // namespace sph::gui
