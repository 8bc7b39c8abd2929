// Water at rest in the 3D tank stays at rest with P = rho0 g (H - z) (dx = 0.05: 1000 fluid and 2640 wall
// particles, t = 0.2 s, after the start-up wave of t ~ 0.1 s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sph/world.h"

namespace sph {
namespace {

TEST(HydrostaticTank3d, MidDepthPressureWithinTwoPercentAndTheWaterAtRest) {
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank_3d");
  cfg.validate();
  World w(cfg);
  ASSERT_EQ(w.particles().dim(), 3);
  w.advance_to(0.2);
  const double err = w.report().reference_value("err_mid"), l1 = w.report().reference_value("L1_p_rel");
  const double v_max = w.report().diagnostics().v_max;
  std::printf("3D tank, t = 0.2: |p_mid/exact - 1| = %.4f, L1(P)/(rho0 g H) = %.4f, v_max = %.3g m/s\n", err, l1, v_max);
  EXPECT_LT(err, 0.02);    // measured 0.27%
  EXPECT_LT(l1, 0.01);     // measured 0.41%
  EXPECT_LT(v_max, 0.05);  // the free-fall speed sqrt(2 g H) is 3.1 m/s; measured 0.031 (0.015 at t = 0.5)
  // no particle went through a side wall or the floor (the walls' inner faces are x, y = 0 and 0.5, z = 0)
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    for (int a : {0, 1}) {
      ASSERT_GT(p.x[a][i], 0.0) << "fluid particle " << i << " outside a side wall";
      ASSERT_LT(p.x[a][i], 0.5) << "fluid particle " << i << " outside a side wall";
    }
    ASSERT_GT(p.x[2][i], 0.0) << "fluid particle " << i << " below the floor";
  }
}

}  // namespace
}  // namespace sph
