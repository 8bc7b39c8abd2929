// Dam breaks at dx = a/20 (800 fluid particles): no fluid particle ever crosses a wall, for every force
// formulation and both wall types; the surge front against the measured fronts; and the dam break on a
// slope (Lennard-Jones walls, seed 001 §7.2) comes to rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sph/world.h"

namespace sph {
namespace {

RunConfig dam(const std::string& force, const std::string& walls) {
  RunConfig cfg = RunConfig::from_scene("dam_break");
  cfg.set("scene.dx", "0.05", "test");
  cfg.set("physics.force", force, "test");
  cfg.set("physics.walls", walls, "test");
  if (force == "standard") cfg.set("physics.xsph", "on", "test");
  cfg.validate();
  return cfg;
}

/// Steps to t, checking after every step that the fluid is inside the tank [0, 4a] x [0, ...): the wall
/// particles' first layer lies dx/2 outside those faces, so a fluid centre beyond it has crossed a wall.
/// Returns the largest speed seen.
double run_inside(World& w, double t_end) {
  const double a = w.config().values.at("a"), dx = w.config().values.at("dx"), L = 4.0 * a;
  double vmax = 0.0;
  while (w.time() < t_end) {
    w.step(t_end - w.time());
    const Particles& p = w.particles();
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      const double x = p.x[0][i], y = p.x[1][i];
      if (x < -0.5 * dx || x > L + 0.5 * dx || y < -0.5 * dx) {
        ADD_FAILURE() << "particle " << p.id[i] << " crossed a wall at t = " << w.time() << ": (" << x << ", " << y
                      << ")";
        return vmax;
      }
    }
    vmax = std::max(vmax, w.report().diagnostics().v_max);
  }
  return vmax;
}

class DamBreakTank : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(DamBreakTank, NoParticleCrossesAWall) {
  const auto [force, walls] = GetParam();
  World w(dam(force, walls));
  // T = t sqrt(2 g / a) = 3.1: the surge reaches the far wall (Z/a = 4) at T ~ 3
  const double vmax = run_inside(w, 0.7);
  std::printf("dam_break %s / %s: v_max = %.3g m/s, front Z/a = %.3f at T = %.2f\n", force, walls, vmax,
              w.report().reference_value("front"), w.report().reference_value("T"));
  // no particle is flung out: the free-fall speed from the column top is sqrt(2 g 2a) = 6.3 m/s
  EXPECT_LT(vmax, 9.0);
}

INSTANTIATE_TEST_SUITE_P(Formulations, DamBreakTank,
                         ::testing::Values(std::pair{"standard", "dummy"}, std::pair{"standard_corrected", "dummy"},
                                           std::pair{"corrected", "dummy"}, std::pair{"standard", "lennard_jones"},
                                           std::pair{"standard_corrected", "lennard_jones"},
                                           std::pair{"corrected", "lennard_jones"}));

TEST(DamBreakFront, WithinFivePercentOfTheMeasuredFronts) {
  // The scene as it ships (dx = a/40, standard-corrected, dummy walls): the surge front against the nearer
  // of Martin & Moyce 1952 and Koshizuka & Oka 1996 wherever they have data, for T <= 2.5 (the required
  // criterion). Measured 0.5-4.3% at T = 0.44 ... 2.21 (largest at T = 1.77).
  World w(RunConfig::from_scene("dam_break"));
  const double t_end = 2.5 / std::sqrt(2.0 * 9.81 / 1.0);  // T = t sqrt(2 g / a), a = 1 m
  double worst = 0.0, worst_T = 0.0;
  int compared = 0;
  while (w.time() < t_end) {
    w.advance_to(std::min(t_end, w.time() + 0.02));
    const double err = w.report().reference_value("err_data");
    if (std::isnan(err)) continue;
    ++compared;
    if (err > worst) { worst = err; worst_T = w.report().reference_value("T"); }
  }
  std::printf("dam_break front: largest error %.2f%% at T = %.2f over %d comparisons\n", 100 * worst, worst_T, compared);
  EXPECT_GT(compared, 20);
  EXPECT_LT(worst, 0.05);
}

class DamBreakSlope : public ::testing::TestWithParam<const char*> {};

TEST_P(DamBreakSlope, ComesToRest) {
  RunConfig cfg = RunConfig::from_scene("dam_break_slope");
  cfg.set("scene.dx", "0.04", "test");
  const std::string force = GetParam();
  cfg.set("physics.force", force, "test");
  cfg.set("physics.xsph", force == "standard" ? "on" : "none", "test");
  cfg.validate();
  World w(cfg);
  double peak = 0.0, E = 0.0, vmax = 0.0;
  const double t_end = 5.0;  // the seed's water is at rest by 4.5 s
  while (w.time() < t_end) {
    w.step(t_end - w.time());
    const Diagnostics d = w.report().diagnostics();
    E = d.E_kin;
    peak = std::max(peak, E);
    vmax = std::max(vmax, d.v_max);
  }
  std::printf("dam_break_slope %s: peak E_kin = %.4g J/m, at t = 5 s %.4g J/m (%.2e of the peak), v_max %.3g m/s\n",
              force.c_str(), peak, E, E / peak, vmax);
  EXPECT_GT(peak, 10.0);        // it did flow (measured 222-250 J/m at t = 0.3 s)
  EXPECT_LT(E, 0.01 * peak);    // the required criterion (measured 1e-4 to 6e-4)
  EXPECT_LT(vmax, 2.0 * std::sqrt(2.0 * 9.81 * 0.6));  // nothing is flung out of the tank
}

INSTANTIATE_TEST_SUITE_P(Formulations, DamBreakSlope, ::testing::Values("standard", "standard_corrected", "corrected"));

}  // namespace
}  // namespace sph
