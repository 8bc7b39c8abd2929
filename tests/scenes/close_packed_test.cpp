// Close-packed lattices: they fill the box at the asked spacing, every particle has the same nearest
// distance (also across periodic faces), and hexagonal/BCC is what they are (6 / 8 nearest neighbours).
#include "close_packed.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sph::scenes {
namespace {

double periodic_gap(double d, double length) { return d - length * std::round(d / length); }

/// Nearest distance and how many neighbours lie within 1.001 of it, for particle i (brute force,
/// periodic on every used axis).
std::pair<double, int> nearest(const Lattice& l, std::size_t i, const Vec3& box, int dim) {
  double best = 1e300;
  std::vector<double> d(l.x.size());
  for (std::size_t j = 0; j < l.x.size(); ++j) {
    if (j == i) continue;
    Vec3 r = l.x[j] - l.x[i];
    r.x = periodic_gap(r.x, box.x);
    r.y = dim > 1 ? periodic_gap(r.y, box.y) : 0.0;
    r.z = dim > 2 ? periodic_gap(r.z, box.z) : 0.0;
    d[j] = r.norm();
    best = std::min(best, d[j]);
  }
  int count = 0;
  for (std::size_t j = 0; j < l.x.size(); ++j)
    if (j != i && d[j] < best * 1.001) ++count;
  return {best, count};
}

TEST(ClosePacked, HexagonalIn2DTilesAPeriodicBox) {
  const Vec3 lo{0, 0, 0}, hi{1, 1, 1}, box{1, 1, 1};
  const Lattice l = close_packed(2, lo, hi, 0.05);
  // about 1/0.05^2 = 400 particles; rounding of the row counts moves it by a few percent at most
  EXPECT_NEAR(static_cast<double>(l.x.size()), 400.0, 0.08 * 400);
  EXPECT_NEAR(l.spacing, 1.0 / std::sqrt(static_cast<double>(l.x.size())), 1e-12);
  const auto [d0, n0] = nearest(l, 0, box, 2);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    ASSERT_GE(l.x[i].x, 0.0);
    ASSERT_LT(l.x[i].x, 1.0);
    ASSERT_GE(l.x[i].y, 0.0);
    ASSERT_LT(l.x[i].y, 1.0);
    const auto [d, n] = nearest(l, i, box, 2);
    // the rows are stretched to tile the box: the two nearest shells differ by under 5%
    ASSERT_NEAR(d, d0, 0.05 * d0) << i;
    ASSERT_GE(n, 2) << i;
  }
  EXPECT_NEAR(d0, l.spacing * std::sqrt(2.0 / std::sqrt(3.0)), 0.05 * d0);
}

TEST(ClosePacked, ExactHexagonHasSixNeighbours) {
  // a box whose height is an even number of exact hexagonal rows: every particle has 6 at one distance
  const double dx = 0.1, dy = dx * std::sqrt(3.0) / 2.0;
  const Vec3 lo{0, 0, 0}, hi{1.0, 10 * dy, 1}, box{1.0, 10 * dy, 1};
  const Lattice l = close_packed(2, lo, hi, std::sqrt(dx * dy));
  ASSERT_EQ(l.x.size(), 100u);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    const auto [d, n] = nearest(l, i, box, 2);
    ASSERT_NEAR(d, dx, 1e-12);
    ASSERT_EQ(n, 6) << i;
  }
}

TEST(ClosePacked, BodyCentredCubicIn3DHasEightNeighbours) {
  const Vec3 lo{-0.5, -0.5, -0.5}, hi{0.5, 0.5, 0.5}, box{1, 1, 1};
  const double s = 1.0 / std::cbrt(2.0 * 6 * 6 * 6);  // 6 cubes per side, 432 particles
  const Lattice l = close_packed(3, lo, hi, s);
  ASSERT_EQ(l.x.size(), 432u);
  EXPECT_NEAR(l.spacing, s, 1e-12);
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    const auto [d, n] = nearest(l, i, box, 3);
    ASSERT_NEAR(d, std::sqrt(3.0) / 2.0 / 6.0, 1e-12);  // half the cube's diagonal
    ASSERT_EQ(n, 8) << i;
  }
}

TEST(ClosePacked, RefusesANonPositiveSpacing) {
  EXPECT_THROW(close_packed(2, {0, 0, 0}, {1, 1, 1}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace sph::scenes
