// The incompressible liquid (physics.eos = dfsph, assets/scenes/*_dfsph.json) on seed 001's scenes:
//  - the elliptical drop's major semi-axis follows the incompressible ODE within 1% (measured 0.04% at
//    dx = 0.025), its energy is kept within 5% without viscosity (+2.4%) and its momentum stays 0;
//  - the dam break's surge front is within 5% of the nearer measured series for T <= 2.5 (measured 4.5%),
//    with every step's mean density error within liquid.dfsph_eta = 0.1% (the bound);
//  - the hydrostatic tank stays at rest and keeps its height; its bottom rows' pressure is rho0 g times
//    their depth on average over t = 0.2 ... 1, and its mid-depth pressure (the reference's p_mid, mean
//    of the particles within dx of mid-depth) is within 1% of rho0 g H/2 at every 0.01 s of t = 0.2 ... 1
//    (the bound; measured 0.46% at worst, +0.35% on average, with the scene's Wendland C4 at
//    h = 1.8 dx; the M4 at 1.3 dx of the other liquids held it 1% low: engine/scenes/dfsph_liquids.cpp);
//  - kernels wider than the M4 at 1.3 dx (which diverged within a few steps before the Jacobi sweeps'
//    relaxation followed the kernel: physics/dfsph_relaxation.h) keep the drop's density within the
//    tolerance and the 3D tank at rest;
//  - and so at the outputs of `sph run` (every 0.1 s), which World::step lands on without a sliver of a
//    step (integrators/landing_step.h): the step of a quarter of dt that landed on t = 0.7 put the
//    probe 3.6% low.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sph/world.h"

namespace sph {
namespace {

RunConfig asset(const std::string& name) {
  return RunConfig::from_file(std::string(SPH_SOURCE_DIR) + "/assets/scenes/" + name + ".json");
}

TEST(EosDfsph, DropFollowsTheIncompressibleOde) {
  RunConfig cfg = asset("elliptical_drop_dfsph");
  cfg.validate();
  World w(cfg);
  const double E0 = w.report().diagnostics().E_tot;
  double worst = 0.0;
  while (w.time() < cfg.params.time.t_end * (1.0 - 1e-12)) {
    w.step(cfg.params.time.t_end - w.time());
    worst = std::max(worst, w.report().diagnostics().dfsph_error);
  }
  const Diagnostics d = w.report().diagnostics();
  const double err_major = w.report().reference_value("err_major");
  std::printf("drop: err_major %.4f, E %.4g -> %.4g, |P| %.3g, worst mean density error %.3g\n", err_major, E0,
              d.E_tot, std::hypot(d.P[0], d.P[1]), worst);
  EXPECT_LT(err_major, 0.01);
  EXPECT_LT(std::abs(d.E_tot / E0 - 1.0), 0.05);
  EXPECT_LT(std::hypot(d.P[0], d.P[1]), 1e-8 * std::sqrt(2.0 * E0 * 1000.0 * 3.14));  // mass ~ rho0 pi
  EXPECT_LE(worst, cfg.params.liquid.dfsph_eta);
}

TEST(EosDfsph, DamBreakFrontWithinFivePercentAtAMeanDensityErrorBelowOneInAThousand) {
  RunConfig cfg = asset("dam_break_dfsph");
  cfg.validate();
  World w(cfg);
  const double g = -cfg.params.body.gy, a = 1.0;
  double worst_front = 0.0, worst_density = 0.0;
  while (w.time() < 0.6 - 1e-12) {
    w.step(0.6 - w.time());
    const double T = w.time() * std::sqrt(2.0 * g / a);
    const double e = w.report().reference_value("err_data");
    if (T <= 2.5 && std::isfinite(e)) worst_front = std::max(worst_front, e);
    worst_density = std::max(worst_density, w.report().diagnostics().dfsph_error);
  }
  std::printf("dam break: %lld steps to t = 0.6, front error %.4f, worst mean density error %.3g\n",
              static_cast<long long>(w.steps()), worst_front, worst_density);
  EXPECT_LT(worst_front, 0.05);
  EXPECT_LE(worst_density, 1e-3);
}

TEST(EosDfsph, TheSameSceneRunsWithTheTaitEquationForTheABView) {
  // run B of `sph run dam_break_dfsph --compare-set physics.eos=tait` (and the GUI's A/B view): the Tait
  // pressure with a summation density and the standard form beside dummy walls; the walls' Omega was
  // unset there and the first step gave NaN
  RunConfig cfg = RunConfig::from_scene("dam_break_dfsph");
  cfg.set("physics.eos", "tait", "test");
  cfg.validate();
  World w(cfg);
  w.advance_to(0.2);
  const double e = w.report().reference_value("err_data");
  std::printf("dam break, Tait beside DFSPH's physics: %lld steps to t = 0.2, front error %.4f\n",
              static_cast<long long>(w.steps()), e);
  EXPECT_LT(e, 0.05);  // measured 4.1% at t = 0.6
}

TEST(EosDfsph, TankKeepsItsVolumeAndHoldsTheWeightOfItsWater) {
  RunConfig cfg = asset("hydrostatic_tank_dfsph");
  cfg.validate();
  World w(cfg);
  const double H = cfg.values.at("depth"), dx = cfg.values.at("dx"), g = -cfg.params.body.gy;
  double ratio = 0.0, worst_v = 0.0, mid = 0.0, mid_worst = 0.0;
  int samples = 0;
  for (int k = 1; k <= 100; ++k) {
    w.advance_to(0.01 * k);
    worst_v = std::max(worst_v, w.report().diagnostics().v_max);
    if (k <= 20) continue;  // the start from a lattice settles
    const Particles& p = w.particles();
    double sum = 0.0, want = 0.0;
    for (std::size_t a = 0; a < p.fluid(); ++a)
      if (p.x[1][a] < 4.0 * dx) {
        sum += p[Field::Pressure][a];
        want += cfg.params.liquid.rho0 * g * (H - p.x[1][a]);
      }
    ratio += sum / want;
    double psum = 0.0;
    int count = 0;
    for (std::size_t a = 0; a < p.fluid(); ++a)
      if (std::abs(p.x[1][a] - 0.5 * H) < dx) {
        psum += p[Field::Pressure][a];
        ++count;
      }
    const double r = psum / count / (0.5 * cfg.params.liquid.rho0 * g * H);
    mid += r;
    mid_worst = std::max(mid_worst, std::abs(r - 1.0));
    ++samples;
  }
  ratio /= samples;
  mid /= samples;
  const Particles& p = w.particles();
  double ym = 0.0;
  for (std::size_t a = 0; a < p.fluid(); ++a) ym += p.x[1][a];
  ym /= static_cast<double>(p.fluid());
  std::printf("tank: bottom rows' pressure %.4f of rho0 g depth (mean of %d), mid-depth %.4f of rho0 g H/2 (worst "
              "%.4f off), centre of mass %.5f H, v_max %.3g m/s\n", ratio, samples, mid, mid_worst, ym / H, worst_v);
  EXPECT_NEAR(ym / H, 0.5, 0.005);  // incompressible: the column keeps its height (Tait: -0.25% at c0)
  EXPECT_LT(worst_v, 0.2);          // at rest but for the lattice's settling (free fall from rest: 1.4 m/s at 0.1 m)
  EXPECT_NEAR(ratio, 1.0, 0.01);    // on average the pressure holds the water (momentum; measured 1.0019)
  EXPECT_NEAR(mid, 1.0, 0.01);      // and at mid-depth (measured 1.0035)
  EXPECT_LT(mid_worst, 0.01);       // at every moment, not only on average (measured 0.0046)
}

TEST(EosDfsph, TankPressureAtTheOutputsOfSphRun) {
  RunConfig cfg = asset("hydrostatic_tank_dfsph");
  cfg.validate();
  World w(cfg);
  double worst = 0.0;
  for (int k = 1; k <= 5; ++k) {  // as `sph run` steps to its outputs (time.dt_out = 0.1 s)
    const double t_out = 0.1 * k;
    while (w.time() < t_out * (1.0 - 1e-14)) w.step(t_out - w.time());
    const double e = w.report().reference_value("err_mid");
    std::printf("t = %.1f: mid-depth pressure off by %.4f\n", w.time(), e);
    worst = std::max(worst, e);
  }
  EXPECT_LT(worst, 0.01);  // measured 0.0049 (M4 at 1.3 dx: 0.0104; with the sliver steps 0.0175)
}

TEST(EosDfsph, WideKernelsKeepTheDensityAndTheWaterAtRest) {
  // the drop for 20 steps at kernels whose sweeps diverged at the old relaxation (w lambda_max 3.4, 2.8)
  for (const auto& [kernel, eta] : {std::pair{"M4", "2.0"}, std::pair{"wendland_c2", "2.0"}}) {
    RunConfig cfg = asset("elliptical_drop_dfsph");
    cfg.set("kernel.type", kernel, "test");
    cfg.set("kernel.eta", eta, "test");
    cfg.validate();
    World w(cfg);
    double worst = 0.0;
    for (int k = 0; k < 20; ++k) {
      ASSERT_NO_THROW(w.step()) << kernel;
      worst = std::max(worst, w.report().diagnostics().dfsph_error);
    }
    std::printf("drop with %s at h = %s dx: worst mean density error %.3g\n", kernel, eta, worst);
    EXPECT_LE(worst, cfg.params.liquid.dfsph_eta) << kernel;
  }
  // the 3D tank (w lambda_max 2.2 at the old 0.3 in 3D: at dx 0.05 it diverged before t = 0.1)
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank_3d");
  for (const auto& [k, v] : {std::pair{"physics.eos", "dfsph"}, {"physics.density", "summation"},
                             {"physics.smoothing", "fixed"}, {"physics.force", "standard"},
                             {"physics.viscosity", "none"}, {"scene.dx", "0.0625"}, {"kernel.eta", "1.5"}})
    cfg.set(k, v, "test");
  cfg.validate();
  World w(cfg);
  double v_max = 0.0;
  while (w.time() < 0.1 - 1e-12) {
    ASSERT_NO_THROW(w.step(0.1 - w.time()));
    const Particles& p = w.particles();
    for (std::size_t a = 0; a < p.fluid(); ++a) v_max = std::max(v_max, p.vel(a).norm());
  }
  std::printf("3D tank with M4 at h = 1.5 dx: v_max %.3g m/s to t = 0.1\n", v_max);
  EXPECT_LT(v_max, 0.2);  // at rest but for the lattice's settling, as the 2D tank
}

}  // namespace
}  // namespace sph
