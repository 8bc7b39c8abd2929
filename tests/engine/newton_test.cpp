// Newton-Raphson (seed 000 App. B, eq. B.0.2; validation table of App. B.1) and the safeguarded solver
// used by the smoothing-length iteration (seed 000 eq. 3.5.1).
#include "sph/newton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace sph {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(Newton, SeedTableB1) {
  // seed 000 App. B.1: f(x) = e^x - 1 from x0 = 5; the table lists iterations 1..10 (x and f(x)).
  const double table_x[10] = {5.0000000000000000,      4.0067379469990856,       3.0249305909158641,
                              2.0734917826567454,      1.1992377194060950,       0.50066161335099058,
                              0.10679111700110960,     5.50449633221851420E-003, 1.51219809167149263E-005,
                              1.14336572256860209E-010};
  const double table_f[10] = {147.41315910257660,      53.967271638716113,       19.592575349796242,
                              6.9525432459365115,      2.3175870264047935,       0.64981244763369572,
                              0.11270180571282506,     5.51967390767815758E-003, 1.51220952544495191E-005,
                              1.14336540235626671E-010};
  double x[10];
  // The seed's Fortran evaluates exp(x) - 1 (not expm1); doing the same reproduces its rounding.
  ASSERT_EQ(
      newton_sequence([](double t) { return std::exp(t) - 1.0; }, [](double t) { return std::exp(t); }, 5.0, x, 10),
      10);
  for (int k = 0; k < 10; ++k) {
    // The table prints 17 significant digits: 1e-12 relative is far above its rounding, far below any
    // algorithmic difference (every iteration moves x by >= 20 %). Measured: bit-identical.
    EXPECT_NEAR(x[k], table_x[k], 1e-12 * table_x[k]) << "iteration " << k + 1;
    const double f = std::exp(x[k]) - 1.0;
    // f at the last rows carries the cancellation of exp(x) - 1 (absolute ~1e-16, 1e-6 relative of 1e-10);
    // same arithmetic as the seed, so still expected to agree to 1e-12.
    EXPECT_NEAR(f, table_f[k], 1e-12 * table_f[k]) << "iteration " << k + 1;
  }
}

TEST(Newton, QuadraticConvergence) {
  // For f = e^x - 1 the map is x -> x - 1 + e^-x = x^2/2 - x^3/6 + x^4/24 - ..., so
  // e_{k+1}/e_k^2 = f''/(2 f') - e_k/6 + O(e_k^2) with f''/(2 f') = 1/2 at the root.
  double x[12];
  newton_sequence([](double t) { return std::expm1(t); }, [](double t) { return std::exp(t); }, 5.0, x, 12);
  int checked = 0;
  for (int k = 0; k + 1 < 12; ++k) {
    const double e = x[k], e1 = x[k + 1];
    if (e > 0.2 || e1 == 0.0) continue;  // far from the root (the asymptotic form does not yet hold) / done
    const double ratio = e1 / (e * e);
    // Truncation of the series: e^2/24; cancellation in x - expm1(x)/exp(x): ~2 eps / e relative.
    const double tol = e * e / 20.0 + 4.0 * kEps / e;
    EXPECT_NEAR(ratio, 0.5 - e / 6.0, tol) << "k = " << k << ", e_k = " << e;
    EXPECT_NEAR(ratio, 0.5, e / 6.0 + tol);  // -> 1/2
    ++checked;
  }
  EXPECT_GE(checked, 4);  // e_k = 0.107, 5.5e-3, 1.5e-5, 1.1e-10
}

TEST(NewtonBracketed, ConvergesQuadraticallyWithoutSafeguards) {
  std::vector<double> seen;
  auto fn = [&](double x, double& f, double& df) {
    seen.push_back(x);
    f = x * x * x - 8.0;
    df = 3.0 * x * x;
  };
  const NewtonResult r = newton_bracketed(fn, 1.5, 100.0, 1e-12, 50);
  EXPECT_TRUE(r.converged);
  EXPECT_FALSE(r.hit_upper);
  EXPECT_EQ(r.bisections, 0);  // every Newton step stays inside [x/2, 2x] and the bracket
  // The stop test |x_{k+1} - x_k| <= tol x_k with quadratic convergence leaves |x - 2| ~ tol^2 <= ~1e-15.
  EXPECT_NEAR(r.x, 2.0, 4.0 * kEps);
  EXPECT_LE(r.iterations, 7);  // 1.5 -> 2.185 -> 2.013 -> 2.00008 -> ... quadratic: 6 evaluations
  EXPECT_EQ(static_cast<int>(seen.size()), r.iterations);
  EXPECT_EQ(seen.back(), r.x);  // result is a point where f was evaluated
}

TEST(NewtonBracketed, FallsBackWhenNewtonLeavesTheBracket) {
  // f = atan(x - 3): plain Newton diverges from |x0 - 3| > 1.39 (the classic counter-example).
  double plain[6];
  newton_sequence([](double x) { return std::atan(x - 3.0); }, [](double x) { return 1.0 / (1.0 + (x - 3) * (x - 3)); },
                  0.5, plain, 6);
  for (int k = 0; k + 1 < 6; ++k) EXPECT_GT(std::fabs(plain[k + 1] - 3.0), std::fabs(plain[k] - 3.0));

  for (double x0 : {0.5, 5.0, 9.0}) {
    std::vector<double> seen;
    auto fn = [&](double x, double& f, double& df) {
      seen.push_back(x);
      f = std::atan(x - 3.0);
      df = 1.0 / (1.0 + (x - 3.0) * (x - 3.0));
    };
    const double upper = 50.0;
    const NewtonResult r = newton_bracketed(fn, x0, upper, 1e-12, 100);
    EXPECT_TRUE(r.converged) << "x0 = " << x0;
    EXPECT_FALSE(r.hit_upper);
    EXPECT_GT(r.bisections, 0) << "x0 = " << x0 << ": the first Newton step leaves the bracket";
    EXPECT_NEAR(r.x, 3.0, 1e-11) << "x0 = " << x0;  // tol 1e-12 relative to x ~ 3, then quadratic
    EXPECT_LT(r.iterations, 30);
    // Every evaluation stays in (0, upper] and in the bracket known at that time.
    double lo = 0.0, hi = upper;
    for (double x : seen) {
      EXPECT_GT(x, lo) << "x0 = " << x0;
      EXPECT_LE(x, hi) << "x0 = " << x0;
      if (std::atan(x - 3.0) < 0.0)
        lo = x;
      else
        hi = x;
    }
    RecordProperty("atan_iterations_x0_" + std::to_string(x0), r.iterations);
    RecordProperty("atan_bisections_x0_" + std::to_string(x0), r.bisections);
  }
}

TEST(NewtonBracketed, ReportsHitUpperWhenNoRootBelowTheLimit) {
  std::vector<double> seen;
  auto fn = [&](double x, double& f, double& df) {
    seen.push_back(x);
    f = x - 10.0;  // root at 10, above the limit 5
    df = 1.0;
  };
  const NewtonResult r = newton_bracketed(fn, 1.0, 5.0, 1e-10, 200);
  EXPECT_TRUE(r.hit_upper);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.x, 5.0);
  EXPECT_EQ(r.iterations, static_cast<int>(seen.size()));
  for (double x : seen) EXPECT_LE(x, 5.0) << "never evaluated beyond the limit (the list's reach)";
  // f < 0 at the limit itself is the only evidence that no root lies below it (1e-12: the solver may stop
  // a hair short of the limit).
  EXPECT_GE(seen.back(), 5.0 * (1.0 - 1e-12));
  EXPECT_LT(r.iterations, 60);  // growth towards the limit is at least geometric
  RecordProperty("hit_upper_iterations", r.iterations);
}

TEST(NewtonBracketed, ReportsNonConvergenceAtTheIterationCap) {
  std::vector<double> seen;
  auto fn = [&](double x, double& f, double& df) {
    seen.push_back(x);
    f = std::atan(x - 3.0);
    df = 1.0 / (1.0 + (x - 3.0) * (x - 3.0));
  };
  const NewtonResult r = newton_bracketed(fn, 0.5, 50.0, 1e-14, 3);
  EXPECT_FALSE(r.converged);
  EXPECT_FALSE(r.hit_upper);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_EQ(r.x, seen.back());  // the last point where f was evaluated
}

}  // namespace
}  // namespace sph
