// Axis ticks at round numbers and the label formats.
#include <gtest/gtest.h>

#include <cmath>

#include "ticks.h"

namespace sph::render {
namespace {

TEST(Ticks, RoundStepsInsideTheRange) {
  const Ticks t = nice_ticks(0.0, 1.0, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  ASSERT_EQ(t.values.size(), 6u);
  EXPECT_DOUBLE_EQ(t.values.front(), 0.0);
  EXPECT_NEAR(t.values.back(), 1.0, 1e-12);

  const Ticks u = nice_ticks(-0.52, 0.52, 5);  // step 0.2: -0.4 .. 0.4, zero exactly
  EXPECT_DOUBLE_EQ(u.step, 0.2);
  EXPECT_NEAR(u.values.front(), -0.4, 1e-12);
  bool has_zero = false;
  for (double v : u.values) has_zero |= (v == 0.0 && !std::signbit(v));
  EXPECT_TRUE(has_zero);
}

TEST(Ticks, DegenerateRangesGiveNoTicks) {
  EXPECT_TRUE(nice_ticks(1.0, 1.0, 5).values.empty());
  EXPECT_TRUE(nice_ticks(2.0, 1.0, 5).values.empty());
  EXPECT_TRUE(nice_ticks(0.0, INFINITY, 5).values.empty());
}

TEST(Ticks, NiceLimitsWidenOutwards) {
  double lo = 0.118, hi = 1.02;
  nice_limits(lo, hi, 10);
  EXPECT_NEAR(lo, 0.1, 1e-12);
  EXPECT_NEAR(hi, 1.1, 1e-12);
}

TEST(Ticks, LabelsUseTheDecimalsTheStepNeeds) {
  EXPECT_EQ(format_tick(0.4, 0.2), "0.4");
  EXPECT_EQ(format_tick(-0.0000000001, 0.2), "0.0");
  EXPECT_EQ(format_tick(2.0, 1.0), "2");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(2e6, 1e6), "2.0e+06");
}

TEST(Ticks, ValuesHaveFourSignificantDigits) {
  EXPECT_EQ(format_value(0.125), "0.1250");
  EXPECT_EQ(format_value(1.0), "1.000");
  EXPECT_EQ(format_value(123.456), "123.5");
  EXPECT_EQ(format_value(0.0), "0");
  EXPECT_EQ(format_value(2.5e-5), "2.500e-05");
  EXPECT_EQ(format_value(-3.0), "-3.000");
}

}  // namespace
}  // namespace sph::render
