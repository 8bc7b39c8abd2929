// Exact Burgers solutions from the ramp of seed 002 eq. 6c: eq. 22 and the shock after t = a, mass
// conservation (int u dx grows at the inflow flux 1/2), the Cole-Hopf viscous solution against the
// closed form for the step, its PDE residual, its limit eps -> 0 (with the L1 distance ~ eps of the
// corners and of the Taylor shock), t -> 0, bounds and monotonicity; and the seed's error e(h).
#include "reference/burgers_exact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace sph::scenes {
namespace {

// composite 5-point Gauss-Legendre on panels of at most 1/per between consecutive breakpoints
template <class F>
double integrate(F&& f, const std::vector<double>& br, int per) {
  const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                        0.2369268850561891};
  double I = 0.0;
  for (std::size_t p = 0; p + 1 < br.size(); ++p) {
    const int n = std::max(1, static_cast<int>(std::ceil(per * (br[p + 1] - br[p]))));
    const double L = (br[p + 1] - br[p]) / n;
    for (int k = 0; k < n; ++k) {
      const double m = br[p] + (k + 0.5) * L;
      for (int i = 0; i < 5; ++i) I += 0.5 * L * gw[i] * f(m + 0.5 * L * gx[i]);
    }
  }
  return I;
}

TEST(BurgersExact, InviscidIsEq22BeforeTheShock) {
  const double a = 1.0;
  for (double x : {-2.0, 0.0, 0.3, 0.7, 1.0, 3.0}) EXPECT_EQ(burgers_inviscid(x, 0.0, a), burgers_initial(x, a));
  EXPECT_EQ(burgers_initial(0.25, a), 0.75);
  const double t = 0.6;
  EXPECT_EQ(burgers_inviscid(-1.0, t, a), 1.0);
  EXPECT_EQ(burgers_inviscid(0.6, t, a), 1.0);          // x <= t
  EXPECT_DOUBLE_EQ(burgers_inviscid(0.7, t, a), 0.75);  // (a - x)/(a - t)
  EXPECT_DOUBLE_EQ(burgers_inviscid(0.9, t, a), 0.25);
  EXPECT_EQ(burgers_inviscid(1.0, t, a), 0.0);  // x >= a
  EXPECT_EQ(burgers_inviscid(5.0, t, a), 0.0);
  // along a characteristic from the ramp, x = y + t u0(y), u keeps its initial value (seed 002 eq. 4)
  for (double y : {0.1, 0.5, 0.9})
    for (double tt : {0.2, 0.5, 0.95}) {
      const double u0 = burgers_initial(y, a);
      EXPECT_NEAR(burgers_inviscid(y + tt * u0, tt, a), u0, 1e-14) << y << " " << tt;
    }
}

TEST(BurgersExact, InviscidShockMovesAtHalfAndConservesMass) {
  const double a = 1.0;
  for (double t : {1.0, 2.0, 4.0}) {
    const double xs = a + 0.5 * (t - a);
    EXPECT_EQ(burgers_inviscid(xs - 1e-9, t, a), 1.0) << t;
    EXPECT_EQ(burgers_inviscid(xs + 1e-9, t, a), 0.0) << t;
    EXPECT_EQ(burgers_inviscid(xs, t, a), 0.5) << t;
  }
  // d/dt int_L^R u dx = f(u(L)) - f(u(R)) = 1/2 (1^2 - 0^2): midpoint rule on 10^6 cells of [-3, 6]
  // (error at most one cell per jump or kink, 1e-5)
  auto mass = [&](double t) {
    const int n = 1000000;
    const double lo = -3.0, hi = 6.0, dx = (hi - lo) / n;
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += burgers_inviscid(lo + (i + 0.5) * dx, t, a);
    return s * dx;
  };
  const double t1 = 0.5, t2 = 2.5;  // before and after the shock forms at t = a
  EXPECT_NEAR(mass(t2) - mass(t1), 0.5 * (t2 - t1), 1e-5);
}

TEST(BurgersExact, ViscousStepMatchesTheClosedForm) {
  // a = 0 (the step): u = 1 / (1 + exp((x - t/2)/(2 eps)) erfc(-x/sqrt(4 eps t)) / erfc((x - t)/sqrt(4 eps t)))
  for (double eps : {0.01, 0.001})
    for (double t : {0.1, 0.5, 2.0})
      for (double x = -0.4; x <= 1.5; x += 0.05) {
        const double z = (x - 0.5 * t) / (2 * eps);
        if (std::abs(z) > 600) continue;  // the closed form over/underflows, not the solution
        const double s = std::sqrt(4 * eps * t);
        const double exact = 1.0 / (1.0 + std::exp(z) * std::erfc(-x / s) / std::erfc((x - t) / s));
        EXPECT_NEAR(burgers_viscous(x, t, 0.0, eps), exact, 1e-13) << eps << " " << t << " " << x;
      }
}

TEST(BurgersExact, ViscousSolvesThePde) {
  // u_t + u u_x - eps u_xx by central differences of step d = 2e-3 eps in x and t, at points on the ramp,
  // at its corners, where the shock forms and inside the shock layer:
  //   |residual| <= 1e-6 (|u_t| + |u u_x| + eps |u_xx|) + 4e-15 eps / d^2
  // (the truncation error ~ d^2 is below 1e-7 of the terms; the second term is the round-off of u,
  // ~1e-15, in the second difference)
  const double a = 1.0;
  for (double eps : {0.01, 0.001}) {
    const double d = 2e-3 * eps;
    struct P {
      double x, t;
    };
    for (const P p : {P{0.3, 0.2}, P{0.5, 0.5}, P{0.8, 0.8}, P{0.9, 0.8}, P{1.0, 0.8}, P{1.0, 1.0}, P{1.5, 2.0},
                      P{1.5 + 2 * eps, 2.0}, P{1.75, 2.5}, P{0.05, 0.05}}) {
      auto u = [&](double x, double t) { return burgers_viscous(x, t, a, eps); };
      const double ut = (u(p.x, p.t + d) - u(p.x, p.t - d)) / (2 * d);
      const double ux = (u(p.x + d, p.t) - u(p.x - d, p.t)) / (2 * d);
      const double uxx = (u(p.x + d, p.t) - 2 * u(p.x, p.t) + u(p.x - d, p.t)) / (d * d);
      const double v = u(p.x, p.t);
      const double tol = 1e-6 * (std::abs(ut) + std::abs(v * ux) + eps * std::abs(uxx)) + 4e-15 * eps / (d * d);
      EXPECT_NEAR(ut + v * ux - eps * uxx, 0.0, tol) << "eps " << eps << " x " << p.x << " t " << p.t;
    }
  }
}

TEST(BurgersExact, ViscousConservesMass) {
  // the same flux balance as the inviscid solution: d/dt int u dx = 1/2 on [-3, 6]
  const double a = 1.0, t1 = 0.5, t2 = 2.5;
  for (double eps : {0.01, 0.001}) {
    auto mass = [&](double t) {  // panels meet at the corner x = t or the shock x_s
      const double knot = t < a ? t : a + 0.5 * (t - a);
      return integrate([&](double x) { return burgers_viscous(x, t, a, eps); },
                       {-3.0, 0.0, std::min(knot, a), std::max(knot, a), 6.0}, 2000);
    };
    EXPECT_NEAR(mass(t2) - mass(t1), 0.5 * (t2 - t1), 1e-9) << eps;
  }
}

TEST(BurgersExact, ViscousTendsToTheInviscidSolution) {
  const double a = 1.0;
  // pointwise, away from the corners (x = t, x = a) and the shock: the gap falls with eps to round-off
  struct Case {
    double t;
    std::vector<double> x;
  };
  for (const Case& c : {Case{0.8, {-0.3, 0.4, 0.6, 1.2, 1.6}}, Case{2.0, {0.5, 1.0, 1.3, 1.7, 2.5}}}) {
    for (double x : c.x) {
      double prev = 1.0;
      for (double eps : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
        const double gap = std::abs(burgers_viscous(x, c.t, a, eps) - burgers_inviscid(x, c.t, a));
        EXPECT_LE(gap, prev + 1e-14) << "t " << c.t << " x " << x << " eps " << eps;
        prev = gap;
      }
      EXPECT_LE(prev, 1e-12) << "t " << c.t << " x " << x;
    }
  }
  // in L1 the gap is ~ eps: Laplace's method on the Cole-Hopf integral gives at each ramp corner a signed
  // area +-eps ln(a/(a - t)) (from the jump of E'' between the pieces), so 2 eps ln(a/(a - t)) for t < a;
  // after the shock the Taylor profile 1/(1 + exp((x - x_s)/(2 eps))) gives 4 eps ln 2
  for (double t : {0.8, 2.0}) {
    const double xs = a + 0.5 * (t - a);
    const std::vector<double> br = t < a ? std::vector<double>{-0.5, t, a, 3.0} : std::vector<double>{-0.5, xs, 3.0};
    const double slope = t < a ? 2.0 * std::log(a / (a - t)) : 4.0 * std::numbers::ln2;
    double prev = 1.0;
    for (double eps : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
      const double L1 = integrate(
          [&](double x) { return std::abs(burgers_viscous(x, t, a, eps) - burgers_inviscid(x, t, a)); }, br, 2000);
      EXPECT_LT(L1, prev) << "t " << t << " eps " << eps;
      if (eps <= 1e-3) {
        EXPECT_NEAR(L1 / eps, slope, 1e-3 * slope) << "t " << t << " eps " << eps;
      }
      prev = L1;
    }
  }
}

TEST(BurgersExact, ViscousStartsFromTheRamp) {
  const double a = 1.0, eps = 0.01;
  for (double x : {-1.0, -0.2, 0.0, 0.3, 0.5, 0.99, 1.0, 1.5})
    EXPECT_EQ(burgers_viscous(x, 0.0, a, eps), burgers_initial(x, a));
  // t = 1e-10: away from the corners u0 moved along its characteristic (O(t)); at a corner the heat
  // kernel smooths over sqrt(eps t) = 1e-6
  const double t = 1e-10;
  for (double x : {-1.0, -0.2, 0.3, 0.5, 0.8, 1.5})
    EXPECT_NEAR(burgers_viscous(x, t, a, eps), burgers_initial(x, a), 1e-9) << x;
  for (double x : {0.0, 1.0}) EXPECT_NEAR(burgers_viscous(x, t, a, eps), burgers_initial(x, a), 1e-5) << x;
  // eps <= 0 is the inviscid solution
  EXPECT_EQ(burgers_viscous(0.7, 0.6, a, 0.0), burgers_inviscid(0.7, 0.6, a));
}

TEST(BurgersExact, ViscousStaysInTheUnitIntervalAndDecreasesInX) {
  // the maximum principle and the monotonicity of the data (u0 non-increasing stays non-increasing)
  for (double eps : {1e-2, 1e-3, 1e-4})
    for (double t : {0.01, 0.3, 0.99, 1.0, 1.01, 2.0, 5.0}) {
      double prev = 1.0;
      for (int i = 0; i <= 500; ++i) {
        const double x = -1.0 + 0.01 * i, u = burgers_viscous(x, t, 1.0, eps);
        ASSERT_GE(u, -1e-14) << eps << " " << t << " " << x;
        ASSERT_LE(u, 1.0 + 1e-14) << eps << " " << t << " " << x;
        ASSERT_LE(u, prev + 1e-14) << eps << " " << t << " " << x;
        prev = u;
      }
    }
}

TEST(BurgersExact, SeedErrorUsesTheLargestGapOfTheSortedPoints) {
  const std::vector<double> x = {0.0, 1.0, 0.4}, u = {1.0, 2.0, 3.0};
  // sorted gaps 0.4 and 0.6 (the unsorted neighbours 0 -> 1 would give 1); sum |u - x| = 1 + 1 + 2.6
  EXPECT_DOUBLE_EQ(seed_error(x, u, [](double y) { return y; }), 0.6 * 4.6);
  EXPECT_EQ(seed_error(std::vector<double>{0.5}, std::vector<double>{9.0}, [](double) { return 0.0; }), 0.0);
  EXPECT_THROW(seed_error(x, std::vector<double>{1.0}, [](double) { return 0.0; }), std::invalid_argument);
}

}  // namespace
}  // namespace sph::scenes
