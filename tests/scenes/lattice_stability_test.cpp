// Why a resting lattice grows with some kernels (box_lattice with wendland_c2 reached |v| = 6e-3
// by t = 63 from round-off). Linear stability of the lattice, computed here: with the energy equation,
// SPH's grad-h gas keeps du = (P/rho^2) drho exactly, so near rest it is the barotropic system
// P = K rho^gamma, whose accelerations derive from a potential. The stiffness M = -da/dx (central
// differences of the engine's own accelerations) is then symmetric; a negative eigenvalue lambda is a
// mode that grows as exp(sqrt(-lambda) t) from round-off, the kernel's pairing/tensile mode on this
// lattice. The rates are checked against a run of the real scene (ideal gas with the energy equation).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "sph/world.h"

namespace sph {
namespace {

/// box_lattice (seed 000 §4.1.2, n x n, rho = 10, u = 0.05, gamma = 1.4; or its hexagonal lattice of the same
/// density, scene.lattice = 1) as the barotropic gas of the same adiabat, with kernel k at its default eta.
struct Barotropic {
  Barotropic(const std::string& kernel, int n_side, bool hexagonal) {
    spec = *find_scene("box_lattice");
    spec.allow(Slot::Eos, {"polytropic"});
    cfg = RunConfig::from_scene("box_lattice");
    cfg.scene = &spec;
    cfg.set("kernel.type", kernel, "test");
    cfg.set("scene.n_side", std::to_string(n_side), "test");
    cfg.set("scene.lattice", hexagonal ? "1" : "0", "test");  // the scene's own hexagonal lattice: same density
    cfg.params.physics.eos = EosType::Polytropic;
    cfg.params.physics.energy = Toggle::Off;
    const double rho0 = 0.1 * n_side * n_side, P0 = (cfg.params.gas.gamma - 1.0) * rho0 * 0.05;
    cfg.params.gas.K = P0 / std::pow(rho0, cfg.params.gas.gamma);
    cfg.params.h.tol = 1e-13;  // h converged far below the probe displacement
  }
  SceneSpec spec;
  RunConfig cfg;
};

/// Eigenvalues of the symmetrised stiffness -da/dx of the lattice (2 n^2 values, ascending) and the
/// relative asymmetry of the finite-difference matrix.
std::pair<Eigen::VectorXd, double> stiffness_spectrum(const std::string& kernel, int n_side, bool hexagonal) {
  Barotropic b(kernel, n_side, hexagonal);
  World w(b.cfg);
  const std::size_t n = w.particles().fluid();
  const double eps = 1e-6 / n_side;  // of the spacing 1/n: truncation ~1e-12, round-off ~1e-10 of M
  Eigen::MatrixXd M(2 * n, 2 * n);
  auto accel = [&](std::size_t i, int k, double dx) {
    Particles& p = const_cast<Particles&>(w.particles());  // a test probe: move one particle, re-evaluate
    const double x0 = p.x[k][i];
    p.x[k][i] = x0 + dx;
    w.evaluate();
    Eigen::VectorXd a(2 * n);
    for (std::uint32_t j : w.by_id()) for (int c = 0; c < 2; ++c) a[2 * w.particles().id[j] + c] = w.particles().a[c][j];
    p.x[k][i] = x0;
    return a;
  };
  for (std::uint32_t i : w.by_id())
    for (int k = 0; k < 2; ++k)
      M.col(2 * w.particles().id[i] + k) = -(accel(i, k, eps) - accel(i, k, -eps)) / (2 * eps);
  const double asym = (M - M.transpose()).norm() / M.norm();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly);
  return {es.eigenvalues(), asym};
}

bool stable(const Eigen::VectorXd& ev) { return ev[0] >= -1e-8 * ev[ev.size() - 1]; }

// Measured at n = 10, default eta (rates sqrt(-lambda_min) in 1 / time unit):
//   kernel        square lattice          hexagonal lattice
//   M4            stable                  unstable, 0.095 (3 modes)
//   M5            stable                  unstable, 0.378 (75 modes)
//   M6            unstable, 0.112         stable
//   gaussian      unstable, 0.178         stable
//   wendland_c2   unstable, 0.3955        stable
//   wendland_c4   unstable, 0.272         stable
// No lattice is at rest for every kernel: a lattice start must match its kernel (the square lattice
// of seed 000 §4.1.2 is stable with its kernels, M4 and M5).
TEST(LatticeStability, TheSpectrumSaysWhichKernelKeepsWhichLatticeAtRest) {
  struct Case { const char* kernel; bool square, hexagonal; };
  for (const Case c : {Case{"M4", true, false}, Case{"M5", true, false}, Case{"M6", false, true},
                       Case{"gaussian", false, true}, Case{"wendland_c2", false, true}, Case{"wendland_c4", false, true}})
    for (const bool hex : {false, true}) {
      const auto [ev, asym] = stiffness_spectrum(c.kernel, 10, hex);
      // a potential's Hessian: symmetric up to the finite differences' error
      EXPECT_LT(asym, 1e-6) << c.kernel << (hex ? " hexagonal" : " square");
      EXPECT_EQ(stable(ev), hex ? c.hexagonal : c.square)
          << c.kernel << (hex ? " hexagonal" : " square") << ": lambda_min = " << ev[0];
      std::printf("%-12s %-9s lambda_min %10.4g  growth rate %.4g\n", c.kernel, hex ? "hexagonal" : "square", ev[0],
                  stable(ev) ? 0.0 : std::sqrt(-ev[0]));
    }
}

/// Growth rate of max |v| in box_lattice (the real scene: ideal gas, energy equation), fitted to
/// log v_max over 1e-11 < v_max < 1e-5 (after round-off has filled the mode, before it saturates).
double measured_rate(const std::string& kernel, double t_end, double* v_final) {
  RunConfig cfg = RunConfig::from_scene("box_lattice");
  cfg.set("kernel.type", kernel, "test");
  World w(cfg);
  double st = 0, sy = 0, stt = 0, sty = 0;
  int n = 0;
  while (w.time() < t_end) {
    w.step();
    const double v = w.report().diagnostics().v_max;
    if (v > 1e-11 && v < 1e-5) {
      const double y = std::log(v), t = w.time();
      st += t; sy += y; stt += t * t; sty += t * y; ++n;
    }
  }
  *v_final = w.report().diagnostics().v_max;
  return n > 10 ? (n * sty - st * sy) / (n * stt - st * st) : 0.0;
}

TEST(LatticeStability, RunsGrowAtThePredictedRateOrStayAtRest) {
  // Wendland C2 on the square lattice: the fastest mode (0.3955) takes the run from round-off to
  // |v| ~ 1e-5 by t ~ 75; the fitted rate matches the spectrum's within 5%
  const auto [ev, asym] = stiffness_spectrum("wendland_c2", 10, false);
  double v = 0.0;
  const double rate = measured_rate("wendland_c2", 80.0, &v);
  EXPECT_NEAR(rate, std::sqrt(-ev[0]), 0.05 * std::sqrt(-ev[0])) << "final v_max " << v;
  // M4 (the scene's default): at rest to round-off over the same time (below the fit window's 1e-11,
  // where the unstable kernel's mode is already growing; the exact level depends on summation order)
  const double none = measured_rate("M4", 80.0, &v);
  EXPECT_EQ(none, 0.0);
  EXPECT_LT(v, 1e-11);
}

}  // namespace
}  // namespace sph
