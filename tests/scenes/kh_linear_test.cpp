// The linear Kelvin-Helmholtz solver: a thin layer tends to the vortex sheet, incompressible
// (Chandrasekhar §101) and compressible (its dispersion relation, solved here independently), and the
// scene's smooth profile gives a step-independent rate below the sheet's.
#include "reference/kh_linear.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "kh_profile.h"

namespace sph::scenes {
namespace {

constexpr double kK = 4.0 * std::numbers::pi;

ShearLayer mcnally_layer(double L, double P, double half_width) {
  ShearLayer l;
  l.rho = [L](double y) { return kh::density(y, L); };
  l.U = [L](double y) { return kh::velocity(y, L); };
  l.dUdy = [L](double y) { return kh::velocity_slope_lower(y, L); };
  l.y_lo = 0.25 - half_width;
  l.y_hi = 0.25 + half_width;
  l.P = P;
  return l;
}

/// The compressible vortex sheet: rho2 Omega2^2 lambda1 + rho1 Omega1^2 lambda2 = 0 (p and the
/// displacement continuous, p ~ exp(-lambda |y|) on both sides), by a secant iteration.
double compressible_sheet_rate(double P, double gamma) {
  using C = std::complex<double>;
  auto f = [&](C s) {
    auto lam = [&](double rho, C om) {
      C l = std::sqrt(kK * kK + rho * om * om / (gamma * P));
      return l.real() < 0 ? -l : l;
    };
    const C o1 = s + C(0, kK) * kh::kU1, o2 = s + C(0, kK) * kh::kU2;
    return kh::kRho2 * o2 * o2 * lam(kh::kRho1, o1) + kh::kRho1 * o1 * o1 * lam(kh::kRho2, o2);
  };
  C s0(5.0, 2.0), s1(5.5, 2.1), f0 = f(s0), f1 = f(s1);
  for (int i = 0; i < 100 && std::abs(s1 - s0) > 1e-13; ++i) {
    const C s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    s0 = s1; f0 = f1; s1 = s2; f1 = f(s1);
  }
  return s1.real();
}

TEST(KhLinear, ThinIncompressibleLayerIsTheVortexSheet) {
  const double sheet = kh_vortex_sheet_rate(kK, 1.0, 2.0, 1.0);
  EXPECT_NEAR(sheet, kK * std::sqrt(2.0) / 3.0, 1e-12);
  const KhMode m = kh_linear_mode(mcnally_layer(1e-4, 1e7, 0.01), kK, 40000);
  ASSERT_TRUE(m.converged);
  EXPECT_NEAR(m.s.real() / sheet, 1.0, 0.01);  // finite thickness: ~2.2 kL = 0.3% low
  EXPECT_LT(m.s.real(), sheet);
  // the phase speed: the density-weighted mean velocity (1 x 0.5 + 2 x -0.5) / 3 = -1/6
  EXPECT_NEAR(-m.s.imag() / kK, -1.0 / 6.0, 0.01);
}

TEST(KhLinear, ThinCompressibleLayerIsTheCompressibleSheet) {
  const double expect = compressible_sheet_rate(2.5, 5.0 / 3.0);
  const KhMode m = kh_linear_mode(mcnally_layer(1e-4, 2.5, 0.01), kK, 40000);
  ASSERT_TRUE(m.converged);
  EXPECT_LT(expect, kh_vortex_sheet_rate(kK, 1.0, 2.0, 1.0));  // compressibility lowers the rate
  EXPECT_NEAR(m.s.real() / expect, 1.0, 0.01);
}

TEST(KhLinear, SmoothProfileRateIsConvergedAndBelowTheSheet) {
  const ShearLayer l = mcnally_layer(0.025, 2.5, 0.25);
  const KhMode a = kh_linear_mode(l, kK, 2000), b = kh_linear_mode(l, kK, 8000);
  ASSERT_TRUE(a.converged && b.converged);
  EXPECT_NEAR(a.s.real(), b.s.real(), 1e-5);
  // L = 0.025 (kL = 0.31) halves the sheet's 5.92: 2.819 (compressible, P = 2.5); 3.019 incompressible
  EXPECT_NEAR(b.s.real(), 2.8193, 1e-3);
  const KhMode inc = kh_linear_mode(mcnally_layer(0.025, 1e7, 0.25), kK, 8000);
  EXPECT_NEAR(inc.s.real(), 3.0186, 1e-3);
  // a thicker layer grows more slowly
  EXPECT_LT(kh_linear_mode(mcnally_layer(0.05, 2.5, 0.25), kK, 8000).s.real(), b.s.real());
}

}  // namespace
}  // namespace sph::scenes
