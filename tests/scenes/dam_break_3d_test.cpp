// SPHERIC test 2 (dam_break_3d): the gauges read what the particles hold, the measured series are the
// archived ones, and at a coarse spacing the column falls as MARIN's gauge H4 saw it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "reference/kleefsman_data.h"
#include "sph/world.h"

namespace sph {
namespace {

RunConfig coarse(const char* dx) {
  RunConfig cfg = RunConfig::from_scene("dam_break_3d");
  cfg.set("scene.dx", dx, "test");
  cfg.validate();
  return cfg;
}

TEST(DamBreak3d, GaugesReadTheColumnAtRest) {
  World w(coarse("0.05"));
  ASSERT_EQ(w.particles().dim(), 3);
  // H4 stands in the 0.55 m column: the 2D spline over a lattice of columns gives their height
  EXPECT_NEAR(w.report().reference_value("H4"), 0.55, 0.55 * 0.005);
  for (const char* g : {"H1", "H2", "H3", "P1"}) EXPECT_EQ(w.report().reference_value(g), 0.0) << g;  // dry
}

TEST(DamBreak3d, MeasuredSeriesAreTheArchivedOnes) {
  // rows of the MARIN file (Time, P1, H2, H4) the resampling must pass through or near
  EXPECT_NEAR(scenes::kleefsman_h4(0.0), 0.5467, 1e-4);       // first sample, t = 2.2e-5 s: 0.54667
  EXPECT_NEAR(scenes::kleefsman_p1(0.415), 11239.4, 30.0);     // the impact's peak sample, t = 0.41503 s
  EXPECT_NEAR(scenes::kleefsman_h2(0.49), 0.0949, 2e-4);       // t = 0.49003 s: 0.094933
  EXPECT_TRUE(std::isnan(scenes::kleefsman_p1(0.2)));          // P1 is kept for the first impact only
  EXPECT_TRUE(std::isnan(scenes::kleefsman_h2(scenes::kleefsman_end() + 0.01)));
}

TEST(DamBreak3d, ColumnFallsAsGaugeH4MeasuredAndStaysInTheTank) {
  World w(coarse("0.08"));
  w.advance_to(0.3);
  const double h4 = w.report().reference_value("H4"), h4_exp = w.report().reference_value("H4_exp");
  std::printf("dx = 0.08 m, t = 0.3 s: H4 = %.4f m, measured %.4f m\n", h4, h4_exp);
  EXPECT_NEAR(h4, h4_exp, 0.03 * 0.55);  // within 3% of the depth (dx = 0.04: 1.2%)
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    const double x = p.x[0][i], y = p.x[1][i], z = p.x[2][i];
    ASSERT_TRUE(x > 0.0 && x < 3.22 && y > 0.0 && y < 1.0 && z > 0.0) << "fluid particle " << i << " left the tank";
    ASSERT_FALSE(x > 0.6635 && x < 0.8245 && y > 0.2955 && y < 0.6985 && z < 0.161) << "particle " << i << " in the box";
  }
}

}  // namespace
}  // namespace sph
