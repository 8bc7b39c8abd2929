// Seed 000's 2D tube with general states (engine/scenes/tube2d.cpp): the seed's 4:1 tube against the
// exact Riemann solution along x, and equal masses that keep any density ratio exact.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/world.h"
#include "test_util.h"

namespace sph {
namespace {

TEST(Tube2d, SeedTubeFollowsTheRiemannSolutionAlongX) {
  // rho 1 | 0.25, u = 0.05 (P = 0.02 | 0.005), t = 3: the star region is 8 h wide from 32 per length
  double l1[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    RunConfig cfg = RunConfig::from_scene("tube2d");
    cfg.set("scene.n_side", k == 0 ? "16" : "32", "test");
    World w(cfg);
    w.advance_to(3.0);
    l1[k] = w.report().reference_value("L1_rho");
    if (k == 1) {  // measured 5.9e-4 and 1.5e-2
      EXPECT_LT(w.report().reference_value("p_star_err"), 0.01);
      EXPECT_LT(w.report().reference_value("u_star_err"), 0.03);
      EXPECT_GT(w.report().reference()->valid_until(), 3.0);  // the left fan's head reaches x = 0 at t = 1 / c_l = 5.98
    }
  }
  EXPECT_LT(l1[1], 0.012);        // measured 0.0080
  EXPECT_LT(l1[1], 0.75 * l1[0]);  // 0.0132 at 16 per length
}

TEST(Tube2d, AnyDensityRatioKeepsEqualMassesAndExactDensities) {
  // rho_r = 0.3: sqrt(0.3) x 32 = 17.5 rows would round; the column spacing absorbs it, not the density
  RunConfig cfg = RunConfig::from_scene("tube2d");
  cfg.set("scene.n_side", "32", "test");
  cfg.set("scene.rho_r", "0.3", "test");
  World w(cfg);
  std::size_t count = 0;
  const double rho = test::mean_over(w, 2.5, 3.5, [&](std::size_t i) { return w.particles()[Field::Density][i]; }, &count);
  ASSERT_GT(count, 20u);
  EXPECT_NEAR(rho, 0.3, 3e-3 * 0.3);
  const Particles& p = w.particles();
  for (std::size_t i = 1; i < p.fluid(); ++i) ASSERT_EQ(p[Field::Mass][i], p[Field::Mass][0]);
}

}  // namespace
}  // namespace sph
