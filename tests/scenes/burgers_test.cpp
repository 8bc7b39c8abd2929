// The Burgers scenes of seed 002 (finite pointset method): the viscous scheme converges to the viscous
// (Cole-Hopf) solution with order >= 0.9 over N = 240 ... 1920 at t = 0.8 (the required bound), and its
// error against the inviscid eq. 22 stops at the floor the viscosity itself sets; the upwind scheme
// converges to eq. 22 at first order before the shock forms, and (seed 002's non-conservative form)
// leaves the shock at x = a afterwards instead of moving it at the Rankine-Hugoniot speed 1/2; point
// control keeps the points on Gamma_0 and "none" lets them move with the flow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "reference/burgers_exact.h"
#include "sph/convergence.h"
#include "sph/world.h"

namespace sph {
namespace {

ConvergenceResult study(const char* scene, const char* column) {
  ConvergenceStudy s;
  s.key = "scene.n";
  s.values = {240, 480, 960, 1920};
  s.t = 0.8;
  s.column = column;
  const RunConfig base = RunConfig::from_scene(scene);
  ConvergenceResult r = run_convergence(base, resolve_study(base, s));
  for (const ConvergenceRun& run : r.runs)
    std::printf("%s N = %g: %s = %.4g, order %.3f\n", scene, run.value, column, run.error, run.order);
  return r;
}

TEST(BurgersViscous, ConvergesToTheViscousSolutionWithOrderAtLeast09) {
  const ConvergenceResult r = study("burgers_viscous", "e_viscous");
  for (std::size_t k = 1; k < r.runs.size(); ++k) EXPECT_GE(r.runs[k].order, 0.9) << "N = " << r.runs[k].value;
}

TEST(BurgersViscous, ItsErrorAgainstEq22StopsAtTheFloorTheViscositySets) {
  // the viscous solution itself differs from eq. 22 by e(h) = 0.01604 at t = 0.8 (eps = 0.005, a = 1):
  // no viscous scheme can come closer to eq. 22 than that
  std::vector<double> x(1920), gap(1920);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = -0.5 + 2.5 * static_cast<double>(i) / 1919.0;
    gap[i] = scenes::burgers_viscous(x[i], 0.8, 1.0, 0.005);
  }
  const double floor = scenes::seed_error(x, gap, [](double xx) { return scenes::burgers_inviscid(xx, 0.8, 1.0); });
  RunConfig cfg = RunConfig::from_scene("burgers_viscous");
  cfg.set("scene.n", "960", "test");
  World w(cfg);
  while (w.time() < 0.8) w.step(0.8 - w.time());
  EXPECT_NEAR(floor, 0.01604, 1e-4);
  EXPECT_NEAR(w.report().reference_value("e_seed"), floor, 0.02 * floor);
}

TEST(BurgersUpwind, ConvergesToEq22AtFirstOrder) {
  const ConvergenceResult r = study("burgers_upwind", "e_seed");
  for (std::size_t k = 1; k < r.runs.size(); ++k) EXPECT_GE(r.runs[k].order, 0.9) << "N = " << r.runs[k].value;
  EXPECT_LT(r.runs.back().error, 1e-3);
}

TEST(BurgersUpwind, TheSeedsNonConservativeSchemeStallsTheShockAtXEqualsA) {
  // A limitation of seed 002's scheme, kept visible here. The exact shock forms at (a, a) and then moves
  // at the Rankine-Hugoniot speed (1 + 0)/2 (x = 1.3 at t = 1.6). Eq. 21 discretises u u_x, which is
  // zero wherever u = 0, and the re-interpolation onto Gamma_0 passes through the unmoved u = 0 points:
  // nothing ever raises u ahead of the shock, so it stays at x = a. A conservative (flux-form) update
  // would move it; this test fails if the scheme changes behaviour, so the README's caveat is revisited.
  RunConfig cfg = RunConfig::from_scene("burgers_upwind");
  cfg.set("scene.n", "1001", "test");  // spacing 0.0025
  World w(cfg);
  while (w.time() < 1.6) w.step(1.6 - w.time());
  const Particles& p = w.particles();
  double crossing = 0.0;  // where u falls through 1/2, interpolated between the points
  for (std::size_t i = 0; i + 1 < p.fluid(); ++i)
    if (p.v[0][i] >= 0.5 && p.v[0][i + 1] < 0.5)
      crossing = p.x[0][i] + (p.v[0][i] - 0.5) / (p.v[0][i] - p.v[0][i + 1]) * (p.x[0][i + 1] - p.x[0][i]);
  std::printf("shock at t = 1.6: x = %.5f (exact 1.3, scheme stalls at a = 1)\n", crossing);
  EXPECT_NEAR(crossing, 1.0, 2.0 * w.report().spacing());
  EXPECT_GT(w.report().reference_value("e_seed"), 0.25);  // the reference says so: 0.3 of unit jump misplaced
}

TEST(BurgersPointControl, ReinterpolationKeepsGammaZeroAndNoneLetsThePointsMove) {
  for (const char* control : {"reinterpolate", "none"}) {
    RunConfig cfg = RunConfig::from_scene("burgers_viscous");
    cfg.set("fpm.control", control, "test");
    World w(cfg);
    while (w.time() < 0.5) w.step(0.5 - w.time());
    const Particles& p = w.particles();
    double moved = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) moved = std::max(moved, std::abs(p.x[0][i] - p[Field::RestX][i]));
    if (std::string(control) == "reinterpolate") {
      EXPECT_EQ(moved, 0.0);
    } else {
      EXPECT_NEAR(moved, 0.5, 0.02);  // the points at u = 1 travelled u t
    }
  }
}

TEST(BurgersPointControl, MergeSplitKeepsTheGapsBetweenHalfAndThreeHalvesDxAndConverges) {
  RunConfig cfg = RunConfig::from_scene("burgers_viscous");
  cfg.set("fpm.control", "merge_split", "test");
  cfg.set("scene.n", "480", "test");
  World w(cfg);
  while (w.time() < 0.8) w.step(0.8 - w.time());
  const Particles& p = w.particles();
  std::vector<double> x(p.x[0].begin(), p.x[0].begin() + static_cast<std::ptrdiff_t>(p.fluid()));
  std::sort(x.begin(), x.end());
  double lo = 1e9, hi = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    lo = std::min(lo, x[i] - x[i - 1]);
    hi = std::max(hi, x[i] - x[i - 1]);
  }
  const double dx = w.report().spacing();
  std::printf("merge_split, N0 = 480: %zu points at t = 0.8, gaps %.3f ... %.3f dx, e_viscous %.3g\n", p.fluid(),
              lo / dx, hi / dx, w.report().reference_value("e_viscous"));
  EXPECT_NE(p.fluid(), 480u);  // points entered at the inflow end and merged in the compressed ramp
  EXPECT_GE(lo, 0.5 * dx * (1 - 1e-9));
  EXPECT_LE(hi, 1.5 * dx * (1 + 1e-9));
  EXPECT_LT(w.report().reference_value("e_viscous"), 1e-4);  // as close to the viscous solution as re-interpolation
}

}  // namespace
}  // namespace sph
