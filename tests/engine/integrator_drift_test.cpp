// The integrators with a drift velocity (XSPH, seed 001 eq. 47: dx/dt = v + dv_xsph): with constant v,
// zero acceleration and a constant drift d, every scheme moves a particle by exactly (v + d) dt per step;
// an evolved array with rate -y (PhaseSpace::evolved, e.g. rho or u) still decays like e^{-t} at the
// scheme's order; and a drift that depends on the state converges.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sph/integrator.h"

namespace sph {
namespace {

constexpr IntegratorType kAll[] = {IntegratorType::Euler, IntegratorType::Leapfrog, IntegratorType::RK4,
                                   IntegratorType::PredictorCorrector};

/// Three particles in 2D with a drift, and an evolved array y with y' = -y.
struct System {
  static constexpr std::size_t n = 3;
  std::array<std::vector<double>, 3> x, v, a, d;
  std::vector<double> y{1.0, 2.0, 0.5}, rate = std::vector<double>(n, 0.0);
  std::vector<double> d0x{0.05, -0.02, 0.0}, d0y{0.01, 0.03, -0.04};  ///< the constant drift
  bool state_drift = false;  ///< drift = -x instead of the constant one
  PhaseSpace s;

  explicit System(bool evolved) {
    for (int k = 0; k < 3; ++k) {
      x[k].assign(n, 0.0);
      v[k].assign(n, 0.0);
      a[k].assign(n, 0.0);
      d[k].assign(n, 0.0);
    }
    for (std::size_t i = 0; i < n; ++i) {
      x[0][i] = 0.1 + 0.3 * i;
      x[1][i] = 0.7 - 0.2 * i;
      v[0][i] = 0.3;
      v[1][i] = -0.2 + 0.1 * i;
    }
    s.dim = 2;
    s.n = n;
    for (int k = 0; k < 3; ++k) { s.x[k] = &x[k]; s.v[k] = &v[k]; s.a[k] = &a[k]; s.drift[k] = &d[k]; }
    if (evolved) s.evolved.push_back({&y, &rate});
  }
  /// a = 0; the drift refreshed from the state, as the XSPH stage does at every evaluation.
  void eval() {
    for (std::size_t i = 0; i < n; ++i) {
      a[0][i] = a[1][i] = 0.0;
      d[0][i] = state_drift ? -x[0][i] : d0x[i];
      d[1][i] = state_drift ? -x[1][i] : d0y[i];
      rate[i] = -y[i];
    }
  }
};

/// Runs `steps` steps of dt.
void run(System& sys, IntegratorType type, double dt, int steps) {
  auto integ = make_integrator(type);
  const Evaluate eval = [&](double) { sys.eval(); };
  bool current = false;
  for (int k = 0; k < steps; ++k) current = integ->step(sys.s, eval, dt, current);
}

TEST(IntegratorDrift, ConstantDriftMovesByVPlusDPerStep) {
  for (IntegratorType type : kAll) {
    System sys(false);
    const auto x0 = sys.x;
    const auto v0 = sys.v;
    const double dt = 0.01;
    const int steps = 10;
    run(sys, type, dt, steps);
    for (std::size_t i = 0; i < System::n; ++i) {
      const double T = steps * dt;
      // x ~ 1 after 10 steps of rounding (~1e-16 each): 1e-14 leaves a factor 10; a missing or doubled
      // drift errs by |d| T ~ 1e-3
      EXPECT_NEAR(sys.x[0][i], x0[0][i] + T * (v0[0][i] + sys.d0x[i]), 1e-14) << to_string(type);
      EXPECT_NEAR(sys.x[1][i], x0[1][i] + T * (v0[1][i] + sys.d0y[i]), 1e-14) << to_string(type);
      EXPECT_EQ(sys.v[0][i], v0[0][i]) << to_string(type) << ": a = 0 leaves v alone";
      EXPECT_EQ(sys.v[1][i], v0[1][i]) << to_string(type);
      EXPECT_EQ(sys.x[2][i], 0.0) << to_string(type) << ": the unused axis stays untouched";
    }
  }
}

TEST(IntegratorDrift, EvolvedArrayDecaysAtTheSchemesOrder) {
  // y' = -y, y(T) = y0 e^{-T}; |error| at T = 1 for dt = 0.05 and 0.025; the observed order is
  // log2 of the ratio. The linear ODE is in the asymptotic regime at these steps (the next term is
  // dt times smaller): +-0.15 around the order (a stale rate or a wrong weight loses at least 1).
  const struct {
    IntegratorType type;
    double order;
  } cases[] = {{IntegratorType::Euler, 1.0}, {IntegratorType::Leapfrog, 2.0}, {IntegratorType::RK4, 4.0},
               {IntegratorType::PredictorCorrector, 2.0}};
  for (const auto& c : cases) {
    double err[2];
    for (int r = 0; r < 2; ++r) {
      const double dt = 0.05 / (1 << r);
      System sys(true);
      const std::vector<double> y0 = sys.y;
      const auto x0 = sys.x;
      const int steps = static_cast<int>(std::lround(1.0 / dt));
      run(sys, c.type, dt, steps);
      err[r] = 0.0;
      for (std::size_t i = 0; i < System::n; ++i) err[r] = std::max(err[r], std::abs(sys.y[i] - y0[i] * std::exp(-1.0)));
      // meanwhile the constant drift is still integrated exactly (40 steps of rounding)
      EXPECT_NEAR(sys.x[0][0], x0[0][0] + 1.0 * (0.3 + 0.05), 1e-13) << to_string(c.type);
    }
    const double p = std::log2(err[0] / err[1]);
    std::printf("%-20s y' = -y: error %.3e at dt = 0.05, observed order %.3f\n", to_string(c.type), err[0], p);
    EXPECT_NEAR(p, c.order, 0.15) << to_string(c.type);
  }
}

TEST(IntegratorDrift, StateDependentDriftConverges) {
  // v = 0 and drift = -x: x(T) = x0 e^{-T}. RK4 evaluates the drift at each stage and the predictor-corrector
  // at the midpoint, so they keep their order; leapfrog drifts with the last evaluation's correction (see
  // leapfrog.cpp: XSPH is a small smoothing correction), which is a forward-Euler step for this part.
  const struct {
    IntegratorType type;
    double min_order;
  } cases[] = {{IntegratorType::Euler, 0.9}, {IntegratorType::Leapfrog, 0.9}, {IntegratorType::RK4, 3.7},
               {IntegratorType::PredictorCorrector, 1.8}};
  for (const auto& c : cases) {
    double err[2];
    for (int r = 0; r < 2; ++r) {
      const double dt = 0.05 / (1 << r);
      System sys(false);
      sys.state_drift = true;
      for (int k = 0; k < 2; ++k) sys.v[k].assign(System::n, 0.0);
      const auto x0 = sys.x;
      run(sys, c.type, dt, static_cast<int>(std::lround(1.0 / dt)));
      err[r] = 0.0;
      for (int k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < System::n; ++i)
          err[r] = std::max(err[r], std::abs(sys.x[k][i] - x0[k][i] * std::exp(-1.0)));
    }
    const double p = std::log2(err[0] / err[1]);
    std::printf("%-20s dx/dt = -x (drift): error %.3e at dt = 0.05, observed order %.3f\n", to_string(c.type), err[0],
                p);
    EXPECT_GT(p, c.min_order) << to_string(c.type);
    EXPECT_LT(err[0], 0.05) << to_string(c.type);  // and close: e^{-1} = 0.37, first order errs ~dt e^{-1}/2
  }
}

}  // namespace
}  // namespace sph
