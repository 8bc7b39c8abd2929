// The Sedov blast scenes at test resolutions (the default runs are measured with `sph run sedov`): the
// deposit adds exactly E, the blast conserves energy, its shock sits where the self-similar solution
// puts it within the smearing this resolution allows, and the shell stays below the strong-shock jump.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "sph/world.h"

namespace sph {
namespace {

struct BlastRun {
  double dE_start, R_err, dE, rho_peak, L1;
  std::size_t n;
};

BlastRun run_blast(const char* scene, const char* n_side) {
  RunConfig cfg = RunConfig::from_scene(scene);
  cfg.set("scene.n_side", n_side, "test");
  World w(cfg);
  BlastRun r{};
  r.n = w.particles().fluid();
  const Diagnostics d0 = w.report().diagnostics();
  // E0 = E + M u_ambient, M = rho1 V (the box is filled at density 1), u_ambient = p0 / ((gamma-1) rho1)
  const double volume = std::pow(cfg.scene->dim == 2 ? 1.0 : 1.2, cfg.scene->dim);
  r.dE_start = std::abs(d0.E_tot - (1.0 + volume * 1e-5 / (2.0 / 3.0)));
  const auto t0 = std::chrono::steady_clock::now();
  while (w.time() < 0.1) w.step(0.1 - w.time());
  r.R_err = w.report().reference_value("R_err");
  r.dE = w.report().reference_value("dE_rel");
  r.rho_peak = w.report().reference_value("rho_peak");
  r.L1 = w.report().reference_value("L1_rho");
  std::printf("%s n_side = %s (%zu particles): R = %.4f against %.4f (err %.4f), |dE/E| = %.3g, rho_peak = %.3f, "
              "L1(rho) = %.3f, %lld steps, %.1f s\n",
              scene, n_side, r.n, w.report().reference_value("R"), w.report().reference_value("R_exact"), r.R_err, r.dE, r.rho_peak, r.L1,
              static_cast<long long>(w.steps()),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return r;
}

TEST(Sedov, TwoDimensionalBlastFollowsTheSelfSimilarShock) {
  // n_side = 80 (a quarter of the default's particles). Measured: R 2.4% ahead (the half-height of the
  // smeared front leads the jump by about h/2; 1.5% at the default 160), |dE/E| 6.8e-4, peak 2.87 of the exact 4
  const BlastRun r = run_blast("sedov", "80");
  EXPECT_LT(r.dE_start, 1e-12);  // the deposit adds exactly E = 1
  EXPECT_LT(r.R_err, 0.04);
  EXPECT_LT(r.dE, 1e-3);
  EXPECT_GT(r.rho_peak, 2.0);  // a shock compressed the gas ...
  EXPECT_LT(r.rho_peak, 4.0);  // ... not beyond the strong-shock jump (gamma+1)/(gamma-1)
  EXPECT_LT(r.L1, 0.4);
}

TEST(Sedov, ThreeDimensionalBlastAtTestResolution) {
  // n_side = 20 across [-0.6, 0.6]^3 (8192 BCC particles; h = 0.07 against R = 0.46): measured R 11.7% ahead
  // (6.6% at the default 32, 9.1% at 24: first order), |dE/E| 1.0e-3, peak 1.48
  const BlastRun r = run_blast("sedov3d", "20");
  EXPECT_LT(r.dE_start, 1e-12);
  EXPECT_LT(r.R_err, 0.15);
  EXPECT_LT(r.dE, 2e-3);
  EXPECT_GT(r.rho_peak, 1.3);
  EXPECT_LT(r.rho_peak, 4.0);
}

}  // namespace
}  // namespace sph
