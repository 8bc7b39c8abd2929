// The short-range laws of self-gravity: Plummer's closed form, and the tabulated kernel law against
// its definition (enclosed mass, Newton beyond the support, force = -dphi/dr and dphi/dh by finite differences).
#include "gravity/softening.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sph::gravity {
namespace {

TEST(Softening, PlummerIsTheCorrectedSeedFormula) {
  // seed 003 eq. 2.43 with the denominator (r^2 + eps^2)^(3/2)
  PairLaw law;
  law.eps2 = 0.1 * 0.1;
  double f, phi;
  law(0.3 * 0.3, 0.0, 0.0, f, phi);
  EXPECT_DOUBLE_EQ(f, std::pow(0.09 + 0.01, -1.5));
  EXPECT_DOUBLE_EQ(phi, -1.0 / std::sqrt(0.1));
}

class KernelLaw : public ::testing::TestWithParam<KernelType> {};

TEST_P(KernelLaw, NewtonianBeyondTheSupportAndConsistent) {
  const KernelSoftening ks(GetParam());
  const double h = 0.3, S = ks.support();
  EXPECT_NEAR(ks.enclosed(S * (1.0 - 1e-9)), 1.0, 1e-6);
  for (double q = 0.01; q < S; q += 0.01) EXPECT_LE(ks.enclosed(q - 0.01), ks.enclosed(q));  // mass only grows
  // continuous with 1/r^2 and -1/r at the support
  double f_in, p_in, f_out, p_out;
  ks.eval(S * h * (1.0 - 1e-7), h, f_in, p_in);
  ks.eval(S * h * (1.0 + 1e-7), h, f_out, p_out);
  EXPECT_NEAR(f_in / f_out, 1.0, 1e-5);
  EXPECT_NEAR(p_in / p_out, 1.0, 1e-6);
  // the force is -dphi/dr: f r = dphi/dr (central differences, step 1e-4 h)
  for (double q : {0.15, 0.3, 0.7, 1.0, 1.3, 1.9}) {
    if (q >= S) continue;
    const double r = q * h, d = 1e-4 * h;
    double f, p, fa, pa, fb, pb;
    ks.eval(r, h, f, p);
    ks.eval(r + d, h, fa, pa);
    ks.eval(r - d, h, fb, pb);
    EXPECT_NEAR((pa - pb) / (2 * d), f * r, 2e-4 * f * r) << "q = " << q;
    EXPECT_LT(f, 1.0 / (r * r * r));  // softer than a point mass inside the support
  }
  // dphi/dh of the grad-h term against central differences in h (step 1e-4 h); zero beyond the support
  for (double q : {0.0, 0.15, 0.3, 0.7, 1.0, 1.3, 1.9, 2.5}) {
    const double r = q * h, d = 1e-4 * h;
    double f, pa, pb;
    ks.eval(r, h + d, f, pa);
    ks.eval(r, h - d, f, pb);
    const double fd = (pa - pb) / (2 * d), dphi = ks.dphi_dh(r, h);
    if (q >= S) {
      EXPECT_EQ(dphi, 0.0) << "q = " << q;
    } else {
      EXPECT_GT(dphi, 0.0) << "q = " << q;  // a larger h makes phi less negative
      EXPECT_NEAR(dphi, fd, 1e-5 / (h * h)) << "q = " << q;
    }
  }
  // finite at r = 0: the kernel's central density (4 pi / 3) W(0) / h^3 times 1
  double f0, p0;
  ks.eval(0.0, h, f0, p0);
  EXPECT_TRUE(std::isfinite(f0) && std::isfinite(p0));
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelLaw,
                         ::testing::Values(KernelType::M4, KernelType::M5, KernelType::M6, KernelType::Gaussian,
                                           KernelType::WendlandC2, KernelType::WendlandC4));

TEST(Softening, M4MatchesItsClosedForm) {
  // Price & Monaghan 2007 eq. A1 (Monaghan 1992) for M4, 0 <= q < 1: the enclosed mass is
  // M(q) = (4/3) q^3 - (6/5) q^5 + (1/2) q^6, in the kernel normalised with support 2h.
  const KernelSoftening ks(KernelType::M4);
  for (double q : {0.2, 0.5, 0.9})
    EXPECT_NEAR(ks.enclosed(q), 4.0 / 3.0 * std::pow(q, 3) - 1.2 * std::pow(q, 5) + 0.5 * std::pow(q, 6), 1e-6);
}

}  // namespace
}  // namespace sph::gravity
