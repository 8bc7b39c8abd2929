// 1D moving least squares (seed 002 §3.1): exact for quadratics, one-sided fits that see only their side,
// the convergence orders of Theorem 3.2 (f ~ h^3, f' ~ h^2, f'' ~ h), the guard's fallbacks, and
// points with zero weight that change nothing.
#include "fpm/mls.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace sph::fpm {
namespace {

struct Quadratic {
  double A, B, C;  // f = A + B x + C x^2
  double f(double x) const { return A + B * x + C * x * x; }
  double df(double x) const { return B + 2 * C * x; }
  double d2f() const { return 2 * C; }
};

// the scale of the data near xbar: round-off in f_j of relative size u moves f by ~u scale,
// f' by ~u scale / h and f'' by ~u scale / h^2
double data_scale(const Quadratic& q, double xbar, double h) {
  return std::abs(q.f(xbar)) + h * std::abs(q.df(xbar)) + h * h * std::abs(q.d2f());
}

TEST(Mls, ReproducesQuadraticsOnRandomPoints) {
  constexpr double kTol = 1e-10;  // relative to data_scale
  for (unsigned seed = 1; seed <= 8; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int m = 5; m <= 12; ++m) {
      const double xbar = 2.0 * U(rng), h = std::pow(10.0, -1.5 + 1.5 * U(rng));
      const Quadratic q{U(rng), U(rng), U(rng)};
      std::vector<double> x(m), f(m);
      for (int j = 0; j < m; ++j) {
        x[j] = xbar + h * U(rng);
        f[j] = q.f(x[j]);
      }
      const MlsFit fit = mls_fit(xbar, x, f, {.h = h});
      const double s = data_scale(q, xbar, h);
      ASSERT_EQ(fit.order, 2) << "seed " << seed << " m " << m;
      EXPECT_EQ(fit.used, m);
      EXPECT_NEAR(fit.f, q.f(xbar), kTol * s) << "seed " << seed << " m " << m;
      EXPECT_NEAR(fit.df, q.df(xbar), kTol * s / h) << "seed " << seed << " m " << m;
      EXPECT_NEAR(fit.d2f, q.d2f(), kTol * s / (h * h)) << "seed " << seed << " m " << m;
    }
  }
}

TEST(Mls, OneSidedFitsSeeOnlyTheirSideAndReproduceLines) {
  constexpr double kTol = 1e-10;  // relative to data_scale
  const double garbage = std::numeric_limits<double>::quiet_NaN();
  for (unsigned seed = 1; seed <= 8; ++seed) {
    std::mt19937_64 rng(100 + seed);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int m = 5; m <= 12; ++m) {
      for (Side side : {Side::Left, Side::Right}) {
        const double xbar = U(rng), h = 0.05 + 0.5 * (1.0 + U(rng));
        const Quadratic line{U(rng), U(rng), 0.0};
        std::vector<double> x(m), f(m);
        int on_side = 0;
        for (int j = 0; j < m; ++j) {
          // the particle itself (d = 0) belongs to both sides
          x[j] = j == 0 ? xbar : xbar + h * U(rng);
          const bool in = j == 0 || (side == Side::Left ? x[j] < xbar : x[j] > xbar);
          f[j] = in ? line.f(x[j]) : garbage;  // the other side must not be read into any sum
          on_side += in;
        }
        const MlsFit fit = mls_fit(xbar, x, f, {.h = h, .side = side});
        const double s = data_scale(line, xbar, h);
        EXPECT_EQ(fit.used, on_side);
        ASSERT_GE(fit.order, on_side >= 2 ? 1 : 0) << "seed " << seed << " m " << m;
        EXPECT_NEAR(fit.f, line.f(xbar), kTol * s) << "seed " << seed << " m " << m;
        if (fit.order >= 1) {
          EXPECT_NEAR(fit.df, line.df(xbar), kTol * s / h) << "seed " << seed << " m " << m;
        }
        if (fit.order == 2) {
          EXPECT_NEAR(fit.d2f, 0.0, kTol * s / (h * h)) << "seed " << seed << " m " << m;
        }
      }
    }
  }
}

// observed orders of f, f', f'' for sin on uniform points with spacing h/gamma, xbar offset from the grid
// by 0.3 spacings (so that no symmetry cancels the leading error terms), halving h four times
void expect_theorem_orders(Side side, double gamma) {
  const double x0 = 0.4;  // sin, its derivatives and the third derivative are all nonzero here
  double prev[3] = {0, 0, 0};
  double h = 0.2;
  for (int level = 0; level < 5; ++level, h *= 0.5) {
    const double dx = h / gamma;
    std::vector<double> x, f;
    for (int k = -8; k <= 8; ++k) {
      x.push_back(x0 + (k - 0.3) * dx);
      f.push_back(std::sin(x.back()));
    }
    const MlsFit fit = mls_fit(x0, x, f, {.h = h, .side = side});
    ASSERT_EQ(fit.order, 2);
    const double err[3] = {std::abs(fit.f - std::sin(x0)), std::abs(fit.df - std::cos(x0)),
                           std::abs(fit.d2f + std::sin(x0))};
    if (level >= 3) {  // the two finest halvings: asymptotic orders 3, 2, 1 (seed 002 eqs. 13-15, k = 2)
      for (int k = 0; k < 3; ++k) {
        const double order = std::log2(prev[k] / err[k]), expected = 3 - k;
        EXPECT_GE(order, expected - 0.3) << "derivative " << k << " h " << h;
        EXPECT_LE(order, expected + 0.3) << "derivative " << k << " h " << h;  // and not better: sharp
      }
    }
    for (int k = 0; k < 3; ++k) prev[k] = err[k];
  }
}

TEST(Mls, ConvergesAtTheTheoremOrders) {
  expect_theorem_orders(Side::Both, 2.5);   // 5 points
  expect_theorem_orders(Side::Left, 3.5);   // 4 points, at -0.3 to -3.3 spacings
  expect_theorem_orders(Side::Right, 3.5);  // 3 points, at 0.7 to 2.7 spacings
}

TEST(Mls, TwoPointsGiveTheLinearFit) {
  const double xbar = 1.0, h = 0.1;
  const std::vector<double> x = {xbar - 0.03, xbar + 0.05};
  const Quadratic line{0.3, -2.0, 0.0}, parabola{0.3, -2.0, 5.0};
  for (const Quadratic& q : {line, parabola}) {
    const std::vector<double> f = {q.f(x[0]), q.f(x[1])};
    const MlsFit fit = mls_fit(xbar, x, f, {.h = h});
    EXPECT_EQ(fit.order, 1);
    EXPECT_EQ(fit.used, 2);
    EXPECT_EQ(fit.d2f, 0.0);
    // two points, two unknowns: the fit is the chord through them
    const double slope = (f[1] - f[0]) / (x[1] - x[0]);
    EXPECT_NEAR(fit.df, slope, 1e-12 * std::abs(slope));
    EXPECT_NEAR(fit.f, f[0] + slope * (xbar - x[0]), 1e-13);
  }
  const std::vector<double> f = {line.f(x[0]), line.f(x[1])};
  const MlsFit fit = mls_fit(xbar, x, f, {.h = h});
  EXPECT_NEAR(fit.f, line.f(xbar), 1e-13);
  EXPECT_NEAR(fit.df, line.df(xbar), 1e-12);
}

TEST(Mls, OnePointGivesTheConstantAndNoneFails) {
  const std::vector<double> x = {2.0, 3.0}, f = {7.0, -1.0};
  const MlsFit one = mls_fit(2.05, x, f, {.h = 0.1});
  EXPECT_EQ(one.order, 0);
  EXPECT_EQ(one.used, 1);
  EXPECT_EQ(one.f, 7.0);
  EXPECT_EQ(one.df, 0.0);
  EXPECT_EQ(one.d2f, 0.0);
  EXPECT_EQ(mls_fit(2.5, x, f, {.h = 0.1}).order, -1);
  EXPECT_EQ(mls_fit(2.5, x, f, {.h = 0.1}).used, 0);
  EXPECT_EQ(mls_fit(2.0, {}, {}, {.h = 0.1}).order, -1);
  EXPECT_EQ(mls_fit(2.0, x, f, {.h = 0.0}).order, -1);
  EXPECT_EQ(mls_fit(2.01, x, f, {.h = 0.1, .side = Side::Right}).order, -1);  // x = 2 is on the left
  EXPECT_EQ(mls_fit(2.0, x, f, {.h = 0.1, .side = Side::Right}).order, 0);    // d = 0 belongs to both sides
  EXPECT_EQ(mls_fit(2.0, x, f, {.h = 0.1, .side = Side::Right}).f, 7.0);
}

TEST(Mls, CoincidentAndNearlyCoincidentPoints) {
  const double h = 0.5;
  // four points at one position: only the constant is determined, the weighted (here plain) mean
  {
    const std::vector<double> x(4, 0.1), f = {1.0, 2.0, 3.0, 4.0};
    const MlsFit fit = mls_fit(0.0, x, f, {.h = h});
    EXPECT_EQ(fit.order, 0);
    EXPECT_EQ(fit.used, 4);
    EXPECT_NEAR(fit.f, 2.5, 1e-15);
  }
  // two distinct positions (three points): linear, exact for lines
  const Quadratic line{-0.5, 3.0, 0.0};
  {
    const std::vector<double> x = {0.1, 0.1, -0.2};
    const std::vector<double> f = {line.f(0.1), line.f(0.1), line.f(-0.2)};
    const MlsFit fit = mls_fit(0.0, x, f, {.h = h});
    EXPECT_EQ(fit.order, 1);
    EXPECT_NEAR(fit.f, line.f(0.0), 1e-14);
    EXPECT_NEAR(fit.df, line.df(0.0), 1e-13);
  }
  // three distinct positions, two of them 1e-9 h apart: the quadratic normal matrix has
  // rcond ~ 1e-19 < 1e-10, so the linear fit is used
  {
    const std::vector<double> x = {0.1, 0.1 + 0.5e-9, -0.2};
    const std::vector<double> f = {line.f(x[0]), line.f(x[1]), line.f(x[2])};
    const MlsFit fit = mls_fit(0.0, x, f, {.h = h});
    EXPECT_EQ(fit.order, 1);
    EXPECT_NEAR(fit.f, line.f(0.0), 1e-14);
    EXPECT_NEAR(fit.df, line.df(0.0), 1e-13);
    // with the threshold lowered to zero the (ill-conditioned) quadratic is solved instead
    EXPECT_EQ(mls_fit(0.0, x, f, {.h = h, .min_rcond = 0.0}).order, 2);
  }
}

TEST(Mls, UpwindFitsWithFewNeighboursFallBack) {
  // uniform points of spacing dx with the seed's h = 1.5 dx (seed 002 §3.2): a one-sided fit sees itself and
  // one neighbour (linear), at the end of the domain only itself (constant); h = 2.5 dx gives three (quadratic)
  const double dx = 0.1;
  const Quadratic line{1.0, -0.5, 0.0};
  std::vector<double> x, f;
  for (int k = 0; k < 10; ++k) {
    x.push_back(k * dx);
    f.push_back(line.f(x.back()));
  }
  struct Case {
    int i;
    double gamma;
    Side side;
    int order, used;
  };
  for (const Case& c :
       {Case{5, 1.5, Side::Both, 2, 3}, Case{5, 1.5, Side::Left, 1, 2}, Case{5, 1.5, Side::Right, 1, 2},
        Case{0, 1.5, Side::Left, 0, 1}, Case{0, 1.5, Side::Right, 1, 2}, Case{9, 1.5, Side::Right, 0, 1},
        Case{5, 2.5, Side::Left, 2, 3}, Case{0, 2.5, Side::Both, 2, 3}}) {
    const MlsFit fit = mls_fit(x[c.i], x, f, {.h = c.gamma * dx, .side = c.side});
    EXPECT_EQ(fit.order, c.order) << "point " << c.i << " gamma " << c.gamma;
    EXPECT_EQ(fit.used, c.used) << "point " << c.i << " gamma " << c.gamma;
    EXPECT_NEAR(fit.f, line.f(x[c.i]), 1e-14);
    EXPECT_NEAR(fit.df, c.order >= 1 ? line.df(x[c.i]) : 0.0, 1e-12);
  }
}

TEST(Mls, WeightsVanishOutsideTheSupportAndBitwiseNothingChanges) {
  const double xbar = 0.5, h = 0.25;
  // the closed support: d = +-h exactly (0.75 and 0.25) has weight exp(-alpha), the next double beyond not
  {
    const std::vector<double> x = {0.75, std::nextafter(0.75, 1.0), 0.25}, f = {1.0, 2.0, 3.0};
    EXPECT_EQ(mls_fit(xbar, x, f, {.h = h}).used, 2);
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> x, f;
  for (int j = 0; j < 9; ++j) {
    x.push_back(xbar + h * U(rng));
    f.push_back(std::exp(x.back()));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Side side : {Side::Both, Side::Left, Side::Right}) {
    const MlsFit ref = mls_fit(xbar, x, f, {.h = h, .side = side});
    ASSERT_EQ(ref.order, 2);
    // far points (|d| > h) with NaN values, inserted everywhere
    std::vector<double> xf, ff;
    for (std::size_t j = 0; j < x.size(); ++j) {
      xf.push_back(xbar + (j % 2 ? 1.0 : -1.0) * h * (1.0 + 0.3 * (j + 1)));
      ff.push_back(nan);
      xf.push_back(x[j]);
      ff.push_back(f[j]);
    }
    xf.push_back(xbar + 1e6);
    ff.push_back(nan);
    const MlsFit far = mls_fit(xbar, xf, ff, {.h = h, .side = side});
    EXPECT_EQ(far.order, ref.order);
    EXPECT_EQ(far.used, ref.used);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(far.f), std::bit_cast<std::uint64_t>(ref.f));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(far.df), std::bit_cast<std::uint64_t>(ref.df));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(far.d2f), std::bit_cast<std::uint64_t>(ref.d2f));
  }
}

// seed 002 Program 1 as printed (unscaled offsets, data shifted by the nearest value), solved in long
// double by Gaussian elimination with partial pivoting
void program1(double xo, const std::vector<double>& xv, const std::vector<double>& fv, double h, long double out[3]) {
  long double M[3][4] = {};
  std::size_t near = 0;
  for (std::size_t j = 1; j < xv.size(); ++j)
    if (std::abs(xv[j] - xo) < std::abs(xv[near] - xo)) near = j;
  for (std::size_t j = 0; j < xv.size(); ++j) {
    const long double d = static_cast<long double>(xv[j]) - xo;
    if (std::abs(d) > h) continue;
    const long double w = std::exp(-8.0L * (d / h) * (d / h));
    const long double p[3] = {1.0L, d, 0.5L * d * d};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) M[r][c] += w * p[r] * p[c];
      M[r][3] += w * p[r] * (static_cast<long double>(fv[j]) - fv[near]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    int piv = k;
    for (int r = k + 1; r < 3; ++r)
      if (std::abs(M[r][k]) > std::abs(M[piv][k])) piv = r;
    for (int c = 0; c < 4; ++c) std::swap(M[k][c], M[piv][c]);
    for (int r = k + 1; r < 3; ++r) {
      const long double l = M[r][k] / M[k][k];
      for (int c = k; c < 4; ++c) M[r][c] -= l * M[k][c];
    }
  }
  for (int k = 2; k >= 0; --k) {
    long double s = M[k][3];
    for (int c = k + 1; c < 3; ++c) s -= M[k][c] * out[c];
    out[k] = s / M[k][k];
  }
  out[0] += fv[near];
}

TEST(Mls, AgreesWithTheSeedsProgram1) {
  // the scaling by h and the Eigen solve change only round-off: agreement to 1e-9 relative
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const double xbar = U(rng), h = 0.2 + 0.2 * U(rng);
    std::vector<double> x, f;
    for (int j = 0; j < 10; ++j) {
      x.push_back(xbar + 1.3 * h * U(rng));  // some beyond the support
      f.push_back(std::cos(3.0 * x.back()) + x.back());
    }
    long double ref[3];
    program1(xbar, x, f, h, ref);
    const MlsFit fit = mls_fit(xbar, x, f, {.h = h});
    ASSERT_EQ(fit.order, 2);
    const double scale = 1.0 + 3.0 * h + 9.0 * h * h;  // |f| + h |f'| + h^2 |f''| bound
    EXPECT_NEAR(fit.f, static_cast<double>(ref[0]), 1e-9 * scale) << trial;
    EXPECT_NEAR(fit.df, static_cast<double>(ref[1]), 1e-9 * scale / h) << trial;
    EXPECT_NEAR(fit.d2f, static_cast<double>(ref[2]), 1e-9 * scale / (h * h)) << trial;
  }
}

}  // namespace
}  // namespace sph::fpm
