// Ghost particles (seed 000 §4.1.1 periodic box, §4.2.1 mirror walls): periodic images reproduce the
// minimum-image geometry, wall mirrors sit at 2 lo - x with mirrored normal velocity, corners are doubly
// mirrored, and apply_boundaries wraps / reflects real particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

#include "sph/domain.h"
#include "sph/neighbours.h"

namespace sph {
namespace {

struct Rng {  // splitmix64: portable reproducible clouds
  std::uint64_t s;
  double uniform() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
};

Particles cloud(int dim, std::size_t n, const Domain& d, std::uint64_t seed) {
  Particles p(dim, n, FieldSet{}.add(Field::Energy));
  Rng rng{seed};
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) {
      p.x[k][i] = d.lo[k] + d.length(k) * rng.uniform();
      p.v[k][i] = rng.uniform() - 0.5;
    }
    p[Field::Energy][i] = 1.0 + rng.uniform();
  }
  return p;
}

Domain periodic_box(int dim) {
  Domain d;
  d.lo = {-0.5, 0.25, 1.0};
  d.hi = {1.5, 1.25, 2.5};
  for (int k = 0; k < dim; ++k) d.bc[k] = Boundary::Periodic;
  return d;
}

// Positions are produced by one addition x + m L (or 2 lo - x): agreement to a few ulps of the box size.
constexpr double kPosTol = 1e-12;

TEST(Ghosts, PeriodicImagesReproduceMinimumImageDistances) {
  for (int dim = 1; dim <= 3; ++dim) {
    const Domain d = periodic_box(dim);
    Particles p = cloud(dim, 300, d, 100 + dim);
    const double margin = 0.3;  // < L/2 on every axis, so the minimum image is the only close one
    make_ghosts(d, margin, p);
    const std::size_t n = p.size();
    std::size_t through_boundary = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        std::array<double, 3> dmin{0, 0, 0};
        bool wrapped = false;
        for (int k = 0; k < dim; ++k) {
          const double L = d.length(k), direct = p.x[k][i] - p.x[k][j];
          dmin[k] = direct - L * std::round(direct / L);
          wrapped = wrapped || std::fabs(dmin[k] - direct) > 0.5 * L;
        }
        const double r = std::sqrt(dmin[0] * dmin[0] + dmin[1] * dmin[1] + dmin[2] * dmin[2]);
        if (!wrapped || r >= margin) continue;
        ++through_boundary;
        // There must be a ghost of j at x_i - dmin (the image of j nearest to i), within the margin of i.
        bool found = false;
        for (std::size_t g = 0; g < p.ghost_src.size() && !found; ++g) {
          if (p.ghost_src[g] != j) continue;
          bool same = true;
          for (int k = 0; k < dim; ++k) same = same && std::fabs(p.x[k][n + g] - (p.x[k][i] - dmin[k])) < kPosTol;
          found = same;
        }
        EXPECT_TRUE(found) << dim << "D: no image of " << j << " next to " << i << " (distance " << r << ")";
      }
    RecordProperty("pairs_through_boundary_" + std::to_string(dim) + "D", std::to_string(through_boundary));
    EXPECT_GT(through_boundary, 0u) << "set-up must exercise wrapped pairs";
  }
}

TEST(Ghosts, PeriodicGhostsAreExactlyTheImagesInTheMarginBand) {
  // Every ghost is x_j + n L (n != 0, integer per axis) lying in (lo - margin, hi + margin)^d, and every such
  // image exists exactly once. Includes a margin larger than the box (several image layers).
  for (int dim = 1; dim <= 3; ++dim)
    for (double margin : {0.2, 0.9, 2.3}) {
      if (dim == 3 && margin > 1.0) continue;  // keep the 3D case small
      const Domain d = periodic_box(dim);
      Particles p = cloud(dim, dim == 1 ? 50 : 40, d, 200 + dim);
      make_ghosts(d, margin, p);
      const std::size_t n = p.size();
      std::set<std::tuple<std::uint32_t, int, int, int>> got, want;
      for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
        const std::uint32_t s = p.ghost_src[g];
        int m[3] = {0, 0, 0};
        for (int k = 0; k < dim; ++k) {
          m[k] = static_cast<int>(std::lround((p.x[k][n + g] - p.x[k][s]) / d.length(k)));
          EXPECT_NEAR(p.x[k][n + g], p.x[k][s] + m[k] * d.length(k), kPosTol);
        }
        EXPECT_EQ(p.id[n + g], p.id[s]);
        EXPECT_EQ(p.ghost_flip[g], 0) << "periodic images are not mirrored";
        EXPECT_TRUE(got.insert({s, m[0], m[1], m[2]}).second) << "duplicate ghost";
      }
      const int M = static_cast<int>(std::ceil(margin / 1.0)) + 1;  // shortest axis L = 1
      for (std::uint32_t j = 0; j < n; ++j)
        for (int a = -M; a <= M; ++a)
          for (int b = (dim > 1 ? -M : 0); b <= (dim > 1 ? M : 0); ++b)
            for (int c = (dim > 2 ? -M : 0); c <= (dim > 2 ? M : 0); ++c) {
              if (a == 0 && b == 0 && c == 0) continue;
              const int m[3] = {a, b, c};
              bool inside = true;
              for (int k = 0; k < dim; ++k) {
                const double xk = p.x[k][j] + m[k] * d.length(k);
                inside = inside && xk > d.lo[k] - margin && xk < d.hi[k] + margin;
              }
              if (inside) want.insert({j, a, b, c});
            }
      EXPECT_EQ(got, want) << dim << "D margin " << margin;
    }
}

TEST(Ghosts, PeriodicNeighbourCountsEqualMinimumImageCounts) {
  // With ghosts, the neighbour search sees each image exactly once: count of j-images within 2 max(h_i,h_j).
  const int dim = 2;
  const Domain d = periodic_box(dim);
  Particles p = cloud(dim, 400, d, 300);
  std::vector<double> h(p.size());
  Rng rng{301};
  for (double& hi : h) hi = 0.03 * std::pow(5.0, rng.uniform());
  const double hmax = *std::max_element(h.begin(), h.end());
  make_ghosts(d, 2.0 * hmax, p);
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) h.push_back(h[p.ghost_src[g]]);
  NeighbourList nl;
  build_neighbours(p, h, 2.0, nl);
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::size_t expect = 0;
    for (std::size_t j = 0; j < p.size(); ++j)
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b) {
          const double dx = p.x[0][i] - p.x[0][j] - a * d.length(0), dy = p.x[1][i] - p.x[1][j] - b * d.length(1);
          const double R = 2.0 * std::max(h[i], h[j]);
          if (dx * dx + dy * dy < R * R) ++expect;
        }
    EXPECT_EQ(nl.of(i).size(), expect) << "particle " << i;
  }
}

TEST(Ghosts, WallMirrorsAndVelocities) {
  Domain d;
  d.lo = {0.0, -1.0, 0.0};
  d.hi = {2.0, 1.0, 1.0};
  d.bc = {Boundary::Wall, Boundary::Wall, Boundary::Open};
  Particles p = cloud(2, 400, d, 400);
  const double margin = 0.25;
  make_ghosts(d, margin, p);
  copy_ghost_velocity(p);
  copy_ghost_field(p, Field::Energy);
  const std::size_t n = p.size();
  std::set<std::tuple<std::uint32_t, int, int>> got, want;  // (src, side per axis: -1 lo, 0 none, +1 hi)
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    const std::uint32_t s = p.ghost_src[g];
    int side[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const bool flipped = (p.ghost_flip[g] >> k) & 1u;
      const double xs = p.x[k][s], xg = p.x[k][n + g];
      if (!flipped) {
        EXPECT_EQ(xg, xs);
        EXPECT_EQ(p.v[k][n + g], p.v[k][s]);  // tangential component copied exactly
      } else {
        side[k] = xg < d.lo[k] ? -1 : 1;
        const double wall = side[k] < 0 ? d.lo[k] : d.hi[k];
        EXPECT_NEAR(xg, 2.0 * wall - xs, kPosTol);
        EXPECT_NEAR(0.5 * (xg + xs), wall, kPosTol);  // the wall bisects source and mirror
        EXPECT_EQ(p.v[k][n + g], -p.v[k][s]);         // normal component mirrored exactly
        EXPECT_LT(std::fabs(xs - wall), margin);
      }
    }
    EXPECT_NE(p.ghost_flip[g], 0) << "a wall ghost is mirrored on at least one axis";
    EXPECT_EQ(p.x[2][n + g], 0.0);
    EXPECT_EQ(p[Field::Energy][n + g], p[Field::Energy][s]);
    EXPECT_EQ(p.id[n + g], p.id[s]);
    EXPECT_TRUE(got.insert({s, side[0], side[1]}).second) << "duplicate ghost";
  }
  for (std::uint32_t j = 0; j < n; ++j) {
    std::vector<int> sx{0}, sy{0};
    if (p.x[0][j] - d.lo[0] < margin) sx.push_back(-1);
    if (d.hi[0] - p.x[0][j] < margin) sx.push_back(1);
    if (p.x[1][j] - d.lo[1] < margin) sy.push_back(-1);
    if (d.hi[1] - p.x[1][j] < margin) sy.push_back(1);
    for (int a : sx)
      for (int b : sy)
        if (a != 0 || b != 0) want.insert({j, a, b});
  }
  EXPECT_EQ(got, want);
}

TEST(Ghosts, CornerGetsDoublyMirroredGhost) {
  Domain d;
  d.bc = {Boundary::Wall, Boundary::Wall, Boundary::Open};  // unit square
  Particles p(2, 1, FieldSet{});
  p.x[0][0] = 0.05;
  p.x[1][0] = 0.97;
  p.v[0][0] = -0.3;
  p.v[1][0] = 0.7;
  make_ghosts(d, 0.1, p);
  copy_ghost_velocity(p);
  ASSERT_EQ(p.total(), 4u);  // x-mirror, y-mirror and the corner
  bool corner = false;
  for (std::size_t g = 0; g < 3; ++g) {
    const double x = p.x[0][1 + g], y = p.x[1][1 + g];
    if (p.ghost_flip[g] == 3) {
      corner = true;
      EXPECT_NEAR(x, -0.05, kPosTol);
      EXPECT_NEAR(y, 1.03, kPosTol);
      EXPECT_EQ(p.v[0][1 + g], 0.3);  // both components reversed: point reflection through the corner
      EXPECT_EQ(p.v[1][1 + g], -0.7);
    } else if (p.ghost_flip[g] == 1) {
      EXPECT_NEAR(x, -0.05, kPosTol);
      EXPECT_EQ(y, 0.97);
      EXPECT_EQ(p.v[0][1 + g], 0.3);
      EXPECT_EQ(p.v[1][1 + g], 0.7);
    } else {
      EXPECT_EQ(p.ghost_flip[g], 2);
      EXPECT_EQ(x, 0.05);
      EXPECT_NEAR(y, 1.03, kPosTol);
      EXPECT_EQ(p.v[0][1 + g], -0.3);
      EXPECT_EQ(p.v[1][1 + g], -0.7);
    }
  }
  EXPECT_TRUE(corner);
  // Periodic x with a wall in y: the periodic image near the wall is mirrored too (and not flipped in x).
  Domain c = d;
  c.bc = {Boundary::Periodic, Boundary::Wall, Boundary::Open};
  Particles q(2, 1, FieldSet{});
  q.x[0][0] = 0.95;
  q.x[1][0] = 0.02;
  make_ghosts(c, 0.1, q);
  ASSERT_EQ(q.total(), 4u);
  bool found = false;
  for (std::size_t g = 0; g < 3; ++g)
    if (std::fabs(q.x[0][1 + g] + 0.05) < kPosTol && std::fabs(q.x[1][1 + g] + 0.02) < kPosTol) {
      found = true;
      EXPECT_EQ(q.ghost_flip[g], 2);
    }
  EXPECT_TRUE(found);
}

TEST(Ghosts, GhostsAreRebuiltNotAccumulated) {
  const Domain d = periodic_box(2);
  Particles p = cloud(2, 200, d, 500);
  make_ghosts(d, 0.2, p);
  const std::size_t first = p.total();
  make_ghosts(d, 0.2, p);
  EXPECT_EQ(p.total(), first);
  EXPECT_EQ(p.size(), 200u);
}

TEST(Boundaries, PeriodicWrapIntoHalfOpenBox) {
  Domain d;
  d.lo = {-0.5, 2.0, 0.0};
  d.hi = {1.5, 3.0, 1.0};
  d.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  const double xs[] = {1.5, 1.8, -0.8, -0.5, 0.3, 7.25, -9.9, -0.5 - 1e-17, 1.5 - 1e-16, 1.5 + 1e-15};
  const std::size_t n = std::size(xs);
  Particles p(2, n, FieldSet{});
  for (std::size_t i = 0; i < n; ++i) {
    p.x[0][i] = xs[i];
    p.x[1][i] = 2.0 + 0.37 * static_cast<double>(i);  // several beyond hi = 3
    p.v[0][i] = 0.1 * static_cast<double>(i) - 0.4;
    p.v[1][i] = 1.0;
  }
  const Particles before = p;
  apply_boundaries(d, p);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      const double L = d.length(k), x = p.x[k][i];
      EXPECT_GE(x, d.lo[k]) << "i=" << i << " k=" << k;
      EXPECT_LT(x, d.hi[k]) << "i=" << i << " k=" << k;
      const double shifts = (x - before.x[k][i]) / L;
      // Whole box lengths only; fmod is exact, the final add rounds by an ulp of the coordinates (~1e-15).
      EXPECT_NEAR(shifts, std::round(shifts), 1e-12) << "i=" << i << " k=" << k;
      EXPECT_EQ(p.v[k][i], before.v[k][i]);  // wrapping leaves velocity alone
    }
  EXPECT_EQ(p.x[0][0], -0.5);  // x = hi maps to lo
  EXPECT_NEAR(p.x[0][1], -0.2, 1e-15);
  EXPECT_NEAR(p.x[0][2], 1.2, 1e-15);
  // Tiny negative coordinates: x + L rounds to exactly hi, which must still land in [lo, hi).
  Domain unit;
  unit.bc = {Boundary::Periodic, Boundary::Open, Boundary::Open};
  const double tiny[] = {-1e-20, -1e-300, std::nextafter(0.0, -1.0), std::nextafter(-0.5, -1.0)};
  Particles q(1, std::size(tiny), FieldSet{});
  for (std::size_t i = 0; i < std::size(tiny); ++i) q.x[0][i] = tiny[i];
  apply_boundaries(unit, q);
  for (std::size_t i = 0; i < std::size(tiny); ++i) {
    EXPECT_GE(q.x[0][i], 0.0) << tiny[i];
    EXPECT_LT(q.x[0][i], 1.0) << tiny[i];
  }
  EXPECT_EQ(q.x[0][0], 0.0);  // -1e-20 + 1 == 1 in double, so the wrap must give lo
}

TEST(Boundaries, WallReflectsPositionAndNormalVelocity) {
  Domain d;
  d.lo = {0.0, -1.0, 0.0};
  d.hi = {1.0, 1.0, 1.0};
  d.bc = {Boundary::Wall, Boundary::Wall, Boundary::Wall};
  Particles p(3, 4, FieldSet{});
  const double x0[4][3] = {{-0.1, 0.0, 0.5}, {1.05, 0.2, 0.5}, {0.5, -1.2, 1.3}, {0.5, 0.5, 0.5}};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      p.x[k][i] = x0[i][k];
      p.v[k][i] = 0.25 * (k + 1) * (i % 2 ? 1 : -1);
    }
  const Particles before = p;
  apply_boundaries(d, p);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = before.x[k][i];
      const bool crossed = x < d.lo[k] || x > d.hi[k];
      if (crossed) {
        const double wall = x < d.lo[k] ? d.lo[k] : d.hi[k];
        EXPECT_NEAR(p.x[k][i], 2.0 * wall - x, 1e-15);  // specular: same distance inside
        EXPECT_EQ(p.v[k][i], -before.v[k][i]);          // normal velocity reversed
      } else {
        EXPECT_EQ(p.x[k][i], x);
        EXPECT_EQ(p.v[k][i], before.v[k][i]);  // tangential / untouched components kept
      }
      EXPECT_GE(p.x[k][i], d.lo[k]);
      EXPECT_LE(p.x[k][i], d.hi[k]);
    }
  // Kinetic energy is unchanged by a specular bounce.
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(p.vel(i).norm2(), before.vel(i).norm2());
}

TEST(Boundaries, WallCrossingsAreCountedAndEscapesFound) {
  // particles 1 and 3 crossed a wall of [0, 1]; particle 3 is more than a box length beyond it, so its
  // reflection still lies outside: it escaped (the World stops the run, naming it)
  Domain d;
  d.bc = {Boundary::Wall, Boundary::Open, Boundary::Open};
  Particles p(1, 5, FieldSet{});
  const double xs[5] = {0.5, -0.1, 0.9, 2.5, 0.2};
  for (int i = 0; i < 5; ++i) p.x[0][i] = xs[i];
  const WallCrossings w = apply_boundaries(d, p);
  EXPECT_EQ(w.reflected, 2u);
  EXPECT_EQ(w.first_reflected, 1u);
  EXPECT_EQ(w.escaped, 1u);
  EXPECT_EQ(w.first_escaped, 3u);
  Particles inside(1, 2, FieldSet{});
  inside.x[0] = {0.0, 1.0};  // on the walls is inside
  const WallCrossings none = apply_boundaries(d, inside);
  EXPECT_EQ(none.reflected, 0u);
  EXPECT_EQ(none.escaped, 0u);
}

// A margin many times the periodic box (h of a blown-up run) is refused before the ghosts are allocated:
// the soak test found an inspection of such a state building 15 million ghosts of 256 particles. A margin of
// a few box lengths (tiny boxes) still gets all its images.
TEST(Ghosts, AMarginFarBeyondThePeriodicBoxIsRefused) {
  const Domain d = periodic_box(2);
  Particles p = cloud(2, 256, d, 7);
  EXPECT_THROW(make_ghosts(d, 1000.0, p), GhostOverflow);
  EXPECT_EQ(p.total(), p.size());  // nothing allocated
  Particles q = cloud(2, 256, d, 7);
  ASSERT_NO_THROW(make_ghosts(d, 2.5, q));
  EXPECT_GT(q.total(), 256u * 9u);  // at least the 3 x 3 images of the box around it (lengths 2 and 1)
}

}  // namespace
}  // namespace sph
