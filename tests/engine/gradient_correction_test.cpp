// The kernel-gradient correction (seed 001 eqs. 33-37): on a disordered particle set with a free
// boundary, the corrected gradient reproduces constant and linear fields to round-off, where the
// standard SPH gradient does not; ill-conditioned particles fall back to L = I and are counted.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/corrected_kernel.h"
#include "stage_test_util.h"

namespace sph {
namespace {

struct Gradients {
  double max_err_corrected = 0.0;  ///< max |grad f - exact| with G (difference form)
  double max_err_plain = 0.0;      ///< with sum V_b f_b G (no difference): exact too, by the Shepard part
  double max_err_standard = 0.0;   ///< standard sum V_b (f_b - f_a) grad W_ab
};

/// Gradient of f = c0 + g . x at every particle, three ways.
Gradients gradients(test::StageBench& b, double c0, const double g[2], bool interior_only) {
  const Particles& p = b.p;
  const CorrectionFields corr(p);
  Gradients out;
  auto f = [&](std::size_t j) { return c0 + g[0] * p.x[0][j] + g[1] * p.x[1][j]; };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (interior_only) {
      const double x = p.x[0][i], y = p.x[1][i];
      if (x < 0.3 || x > 0.7 || y < 0.3 || y > 0.7) continue;
    }
    double gc[2] = {0, 0}, gp[2] = {0, 0}, gs[2] = {0, 0};
    const double hi = p[Field::H][i];
    for (std::uint32_t j : b.nl.of(i)) {
      const double r[3] = {p.x[0][i] - p.x[0][j], p.x[1][i] - p.x[1][j], 0.0};
      const double rr = std::sqrt(r[0] * r[0] + r[1] * r[1]);
      if (rr >= b.kernel.support() * hi) continue;
      const double V = p[Field::Mass][j] / p[Field::Density][j];
      double G[3];
      corr.gradient(i, r, b.kernel.W(rr, hi), rr > 0 ? b.kernel.dWdr(rr, hi) / rr : 0.0, G);
      const double dW = rr > 0 ? b.kernel.dWdr(rr, hi) / rr : 0.0;
      for (int k = 0; k < 2; ++k) {
        gc[k] += V * (f(j) - f(i)) * G[k];
        gp[k] += V * f(j) * G[k];
        gs[k] += V * (f(j) - f(i)) * r[k] * dW;
      }
    }
    for (int k = 0; k < 2; ++k) {
      out.max_err_corrected = std::max(out.max_err_corrected, std::abs(gc[k] - g[k]));
      out.max_err_plain = std::max(out.max_err_plain, std::abs(gp[k] - g[k]));
      out.max_err_standard = std::max(out.max_err_standard, std::abs(gs[k] - g[k]));
    }
  }
  return out;
}

test::StageBench disordered(double min_rcond) {
  Params prm;
  prm.physics.force = ForceType::StandardCorrected;
  prm.correction.min_rcond = min_rcond;
  auto stage = make_gradient_correction(2);
  const std::size_t n = 20;
  const double dx = 1.0 / n;
  test::StageBench b(prm, 2, n * n, stage->needs() | stage->writes());
  test::jittered_lattice(b.p, n, dx, 0.4, 1.3 * dx, 1000.0);
  b.prepare(FieldSet{}.add(Field::Density));
  EXPECT_TRUE(b.run(*stage));
  return b;
}

TEST(GradientCorrection, LinearFieldsExactOnADisorderedSetWithAFreeBoundary) {
  test::StageBench b = disordered(0.0);  // no fallback: every particle corrected
  EXPECT_EQ(b.stats.correction_fallbacks, 0u);
  const double g[2] = {3.0, -2.0};
  const Gradients all = gradients(b, 7.0, g, false);
  // round-off: |grad f| ~ 3.6, sums of ~20 terms of size f/h ~ 500: 1e-10 is generous
  EXPECT_LT(all.max_err_corrected, 1e-10);
  EXPECT_LT(all.max_err_plain, 1e-9);
  // the standard gradient is off by O(1) at the free boundary and by the disorder inside
  EXPECT_GT(all.max_err_standard, 0.5);
  const Gradients inner = gradients(b, 7.0, g, true);
  EXPECT_LT(inner.max_err_corrected, 1e-10);
  EXPECT_GT(inner.max_err_standard, 0.01);  // measured ~0.3: disorder alone breaks the standard form
}

TEST(GradientCorrection, ConstantFieldsHaveZeroCorrectedGradient) {
  test::StageBench b = disordered(0.0);
  const double zero[2] = {0.0, 0.0};
  const Gradients c = gradients(b, 5.0, zero, false);
  EXPECT_LT(c.max_err_plain, 1e-9);  // sum V_b G_a(b) = 0: exact for constants without the difference
  EXPECT_GT(c.max_err_standard, -1.0);
}

TEST(GradientCorrection, IllConditionedParticlesFallBackAndAreCounted) {
  // Demanding rcond >= 0.9 makes the particles on the edges (one-sided neighbourhoods) fall back.
  test::StageBench b = disordered(0.9);
  const auto& fb = b.p[Field::CorrFallback];
  std::size_t marked = 0, edge_marked = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    marked += fb[i] != 0.0;
    // edge particles (one-sided in x only) are anisotropic, hence poorly conditioned; corners are not:
    // truncated alike in x and y, their moment matrix stays close to a multiple of the identity
    if (b.p.x[0][i] < 0.05 && b.p.x[1][i] > 0.3 && b.p.x[1][i] < 0.7) edge_marked += fb[i] != 0.0;
    if (fb[i] != 0.0) {
      EXPECT_NEAR(b.p[Field::CorrXX][i] * b.p[Field::Shepard][i], 1.0, 1e-14);  // L = A S = I
      EXPECT_EQ(b.p[Field::CorrXY][i], 0.0);
    }
  }
  EXPECT_EQ(marked, b.stats.correction_fallbacks);
  EXPECT_GT(marked, 0u);
  EXPECT_GE(edge_marked, 3u);
  EXPECT_LT(marked, b.p.size() / 2);  // the interior is well conditioned
}

}  // namespace
}  // namespace sph
