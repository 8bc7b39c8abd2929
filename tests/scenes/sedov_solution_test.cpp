// The Sedov-Taylor similarity solution: xi0 against the literature, the strong-shock jump at R(t), the
// energy integral, and the profiles solving the Euler equations (checked by finite differences, so a
// wrong exponent in the closed form would fail here).
#include "reference/sedov_solution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sph::scenes {
namespace {

TEST(SedovSolution, Xi0MatchesTheLiterature) {
  // Kamm & Timmes 2007 (LA-UR-07-2849), gamma = 1.4: alpha = 0.9840 (cylindrical), 0.8510 (spherical), i.e.
  // xi0 = alpha^(-1/(d+2)) = 1.00402, 1.03278 (Taylor 1950: 1.033). gamma = 5/3: 1.15379 (2D) and
  // 1.15167 (3D), alpha = 0.5643 and 0.4936 (from the similarity ODEs).
  struct Case { int d; double gamma, xi0; } cases[] = {{2, 1.4, 1.00402}, {3, 1.4, 1.03278},
                                                       {2, 5.0 / 3.0, 1.15379}, {3, 5.0 / 3.0, 1.15167}};
  for (const Case& c : cases) {
    const SedovSolution s(c.d, c.gamma);
    std::printf("d = %d gamma = %.4f: alpha = %.6f xi0 = %.6f\n", c.d, c.gamma, s.alpha(), s.xi0());
    EXPECT_NEAR(s.xi0(), c.xi0, 2e-5) << "d = " << c.d << " gamma = " << c.gamma;
    EXPECT_NEAR(std::pow(s.alpha(), -1.0 / (c.d + 2.0)), s.xi0(), 1e-12);
  }
}

TEST(SedovSolution, StrongShockJumpAtTheFront) {
  for (int d : {1, 2, 3})
    for (double g : {1.2, 1.4, 5.0 / 3.0}) {
      const SedovSolution s(d, g);
      const double E = 2.5, rho1 = 1.3, t = 0.37, R = s.shock_radius(E, rho1, t);
      // the shock speed by a central difference of R(t), not the formula the solution uses
      const double dt = 1e-6 * t, U = (s.shock_radius(E, rho1, t + dt) - s.shock_radius(E, rho1, t - dt)) / (2 * dt);
      const SedovSolution::State behind = s.state(R * (1 - 1e-9), t, E, rho1);
      // Rankine-Hugoniot for a strong shock into gas at rest (Landau & Lifshitz, Fluid Mechanics, §89)
      EXPECT_NEAR(behind.rho / rho1, (g + 1) / (g - 1), 1e-6 * (g + 1) / (g - 1));
      EXPECT_NEAR(behind.v, 2 * U / (g + 1), 1e-6 * U);
      EXPECT_NEAR(behind.P, 2 * rho1 * U * U / (g + 1), 1e-6 * rho1 * U * U);
      const SedovSolution::State ahead = s.state(R * (1 + 1e-9), t, E, rho1);
      EXPECT_EQ(ahead.rho, rho1);
      EXPECT_EQ(ahead.v, 0.0);
    }
}

TEST(SedovSolution, EnergyIntegralIsE) {
  // a trapezoid rule in r over the flow at t (not the Gauss-Legendre in xi that gave alpha)
  constexpr double kPi = std::numbers::pi;
  for (int d : {1, 2, 3})
    for (double g : {1.4, 5.0 / 3.0}) {
      const SedovSolution s(d, g);
      const double E = 2.5, rho1 = 1.3, t = 0.37, R = s.shock_radius(E, rho1, t);
      const double surface = d == 1 ? 2.0 : d == 2 ? 2 * kPi : 4 * kPi;
      constexpr int n = 20000;
      double sum = 0.0;
      for (int k = 0; k <= n; ++k) {
        const double r = R * k / n;
        const SedovSolution::Shape q = s.solve_xi(r / R);
        const double U = 2 * R / ((d + 2) * t), v2 = 2 * U / (g + 1);
        const double rho = rho1 * (g + 1) / (g - 1) * q.f, v = v2 * q.g, P = 0.5 * (g + 1) * rho1 * v2 * v2 * q.h;
        const double e = (0.5 * rho * v * v + P / (g - 1)) * surface * std::pow(r, d - 1);
        sum += (k == 0 || k == n ? 0.5 : 1.0) * e;
      }
      EXPECT_NEAR(sum * R / n, E, 2e-5 * E) << "d = " << d << " gamma = " << g;
    }
}

TEST(SedovSolution, ProfilesSolveTheEulerEquations) {
  // continuity, radial momentum and entropy (P / rho^gamma constant along a path) by central differences
  // of the exact parametric profiles in r and t; each residual relative to its largest term
  for (int d : {1, 2, 3})
    for (double g : {1.4, 5.0 / 3.0}) {
      const SedovSolution s(d, g);
      const double E = 1.0, rho1 = 1.0, t = 0.5, R = s.shock_radius(E, rho1, t);
      auto flow = [&](double r, double tt) {
        const double Rt = s.shock_radius(E, rho1, tt), U = 2 * Rt / ((d + 2) * tt), v2 = 2 * U / (g + 1);
        const SedovSolution::Shape q = s.solve_xi(r / Rt);
        return SedovSolution::State{rho1 * (g + 1) / (g - 1) * q.f, v2 * q.g, 0.5 * (g + 1) * rho1 * v2 * v2 * q.h};
      };
      for (double xi : {0.5, 0.7, 0.85, 0.95}) {
        const double r = xi * R, hr = 1e-5 * R, ht = 1e-5 * t;
        const auto c = flow(r, t), rp = flow(r + hr, t), rm = flow(r - hr, t), tp = flow(r, t + ht), tm = flow(r, t - ht);
        const double drho_t = (tp.rho - tm.rho) / (2 * ht), drho_r = (rp.rho - rm.rho) / (2 * hr);
        const double dv_t = (tp.v - tm.v) / (2 * ht), dv_r = (rp.v - rm.v) / (2 * hr);
        const double dP_r = (rp.P - rm.P) / (2 * hr);
        auto entropy = [g](const SedovSolution::State& q) { return std::log(q.P) - g * std::log(q.rho); };
        const double ds_t = (entropy(tp) - entropy(tm)) / (2 * ht), ds_r = (entropy(rp) - entropy(rm)) / (2 * hr);
        const double mass[] = {drho_t, c.v * drho_r, c.rho * dv_r, (d - 1) * c.rho * c.v / r};
        const double mom[] = {dv_t, c.v * dv_r, dP_r / c.rho};
        const double ent[] = {ds_t, c.v * ds_r};
        auto check = [&](const double* terms, int n, const char* what) {
          double sum = 0, scale = 0;
          for (int k = 0; k < n; ++k) { sum += terms[k]; scale = std::max(scale, std::abs(terms[k])); }
          EXPECT_LT(std::abs(sum), 1e-5 * scale) << what << " d = " << d << " gamma = " << g << " xi = " << xi;
        };
        check(mass, 4, "continuity");
        check(mom, 3, "momentum");
        check(ent, 2, "entropy");
      }
    }
}

}  // namespace
}  // namespace sph::scenes
