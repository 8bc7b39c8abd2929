// The cell-list neighbour search (seed 002 §3.2) against the O(N^2) reference: same sets for every particle,
// on random clouds with strongly variable h, open / periodic / wall boundaries, degenerate and clustered
// clouds; self-inclusion; and a list order that does not depend on the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sph/domain.h"
#include "sph/neighbours.h"

namespace sph {
namespace {

constexpr double kRadius = 2.0;  // M4 support in units of h

/// Small portable generator (splitmix64), so the clouds are the same with every standard library.
struct Rng {
  std::uint64_t s;
  double uniform() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

/// n particles uniform in the box; h = h0 * 5^u with u uniform in [0,1): a factor 5 between smallest and largest.
Particles cloud(int dim, std::size_t n, const Domain& d, double h0, std::uint64_t seed, std::vector<double>& h) {
  Particles p(dim, n, FieldSet{});
  Rng rng{seed};
  h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) p.x[k][i] = d.lo[k] + d.length(k) * rng.uniform();
    h[i] = h0 * std::pow(5.0, rng.uniform());
  }
  return p;
}

/// Ghosts for the domain's boundaries with a margin that covers the largest search radius; h copied.
void add_ghosts(const Domain& d, Particles& p, std::vector<double>& h) {
  const double hmax = *std::max_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(p.size()));
  make_ghosts(d, kRadius * hmax, p);
  h.resize(p.total());
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) h[p.size() + g] = h[p.ghost_src[g]];
}

/// Asserts that cell list and brute force give the same neighbour set for every real particle, that each
/// list holds i, and returns the mean list length.
double expect_same_as_brute(const Particles& p, const std::vector<double>& h) {
  NeighbourList fast, brute;
  build_neighbours(p, h, kRadius, fast);
  build_neighbours_brute(p, h, kRadius, brute);
  EXPECT_EQ(fast.offset.size(), p.size() + 1);
  EXPECT_EQ(fast.pairs(), brute.pairs());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    auto a = fast.of(i), b = brute.of(i);
    std::vector<std::uint32_t> sa(a.begin(), a.end()), sb(b.begin(), b.end());
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    if (sa != sb && ++mismatches <= 5) ADD_FAILURE() << "particle " << i << ": " << sa.size() << " vs " << sb.size();
    EXPECT_TRUE(std::binary_search(sa.begin(), sa.end(), static_cast<std::uint32_t>(i))) << "i missing from its list";
    EXPECT_EQ(std::adjacent_find(sa.begin(), sa.end()), sa.end()) << "duplicate in the list of " << i;
  }
  EXPECT_EQ(mismatches, 0u);
  return static_cast<double>(fast.pairs()) / static_cast<double>(p.size());
}

Domain box(int dim, Boundary bc) {
  Domain d;
  d.lo = {-0.5, 0.25, 1.0};
  d.hi = {1.5, 1.25, 2.5};
  for (int k = 0; k < dim; ++k) d.bc[k] = bc;
  return d;
}

struct CloudCase {
  int dim;
  std::size_t n;
  double h0;  // smallest h; the largest is 5 h0
};

// Sizes: a few tens of neighbours on average, small enough that the O(N^2) reference stays fast.
const CloudCase kClouds[] = {{1, 400, 0.004}, {2, 1200, 0.012}, {3, 1500, 0.05}};

TEST(CellList, MatchesBruteForceOpen) {
  for (const auto& c : kClouds) {
    std::vector<double> h;
    Particles p = cloud(c.dim, c.n, box(c.dim, Boundary::Open), c.h0, 11 + c.dim, h);
    const double mean = expect_same_as_brute(p, h);
    RecordProperty("mean_neighbours_open_" + std::to_string(c.dim) + "D", std::to_string(mean));
    EXPECT_GT(mean, 5.0) << "the test must exercise real lists";  // sanity of the set-up, not of the code
  }
}

TEST(CellList, MatchesBruteForcePeriodic) {
  for (const auto& c : kClouds) {
    std::vector<double> h;
    const Domain d = box(c.dim, Boundary::Periodic);
    Particles p = cloud(c.dim, c.n, d, c.h0, 21 + c.dim, h);
    add_ghosts(d, p, h);
    EXPECT_GT(p.total(), p.size());
    const double mean = expect_same_as_brute(p, h);
    RecordProperty("mean_neighbours_periodic_" + std::to_string(c.dim) + "D", std::to_string(mean));
  }
}

TEST(CellList, MatchesBruteForceWalls) {
  for (const auto& c : kClouds) {
    std::vector<double> h;
    const Domain d = box(c.dim, Boundary::Wall);
    Particles p = cloud(c.dim, c.n, d, c.h0, 31 + c.dim, h);
    add_ghosts(d, p, h);
    EXPECT_GT(p.total(), p.size());
    const double mean = expect_same_as_brute(p, h);
    RecordProperty("mean_neighbours_wall_" + std::to_string(c.dim) + "D", std::to_string(mean));
  }
}

TEST(CellList, MatchesBruteForceMixedBoundaries) {
  // 3D: periodic x, walls in y, open z (a channel), so periodic-then-wall corner ghosts appear.
  std::vector<double> h;
  Domain d = box(3, Boundary::Open);
  d.bc = {Boundary::Periodic, Boundary::Wall, Boundary::Open};
  Particles p = cloud(3, 1200, d, 0.05, 41, h);
  add_ghosts(d, p, h);
  expect_same_as_brute(p, h);
}

TEST(CellList, MatchesBruteForceDegenerateAndClustered) {
  // A 3D cloud flat in z (zero extent on one axis) ...
  {
    std::vector<double> h;
    Particles p = cloud(3, 800, box(3, Boundary::Open), 0.02, 51, h);
    for (std::size_t i = 0; i < p.size(); ++i) p.x[2][i] = 1.7;
    expect_same_as_brute(p, h);
  }
  // ... two tight clusters 1e4 apart (the cell count cap makes cells much larger than the radius) ...
  {
    std::vector<double> h;
    Particles p = cloud(2, 600, box(2, Boundary::Open), 0.005, 52, h);
    for (std::size_t i = 0; i < p.size(); i += 2) p.x[0][i] += 1e4;
    expect_same_as_brute(p, h);
  }
  // ... and coincident particles (distance 0 is a neighbour).
  {
    std::vector<double> h;
    Particles p = cloud(2, 50, box(2, Boundary::Open), 0.01, 53, h);
    for (std::size_t i = 0; i < p.size(); ++i) p.x[0][i] = p.x[1][i] = 0.3;
    expect_same_as_brute(p, h);
    NeighbourList nl;
    build_neighbours(p, h, kRadius, nl);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(nl.of(i).size(), p.size());
  }
}

TEST(CellList, PairCriterionIsSymmetric) {
  // |r_ij| < R max(h_i, h_j) is symmetric, so for real pairs j in list(i) <=> i in list(j).
  std::vector<double> h;
  Particles p = cloud(2, 800, box(2, Boundary::Open), 0.01, 61, h);
  NeighbourList nl;
  build_neighbours(p, h, kRadius, nl);
  std::vector<std::vector<std::uint32_t>> sorted(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    sorted[i].assign(nl.of(i).begin(), nl.of(i).end());
    std::sort(sorted[i].begin(), sorted[i].end());
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j : sorted[i])
      EXPECT_TRUE(std::binary_search(sorted[j].begin(), sorted[j].end(), static_cast<std::uint32_t>(i)))
          << i << " sees " << j << " but not the reverse";
}

TEST(CellList, ListOrderIndependentOfThreadCount) {
  std::vector<double> h;
  const Domain d = box(3, Boundary::Periodic);
  // above kParallelMin (engine/src/core/parallel.h): below it the search runs on one thread anyway
  Particles p = cloud(3, 6000, d, 0.03, 71, h);
  add_ghosts(d, p, h);
  const int saved = omp_get_max_threads();
  NeighbourList one, two;
  omp_set_num_threads(1);
  build_neighbours(p, h, kRadius, one);
  omp_set_num_threads(2);
  build_neighbours(p, h, kRadius, two);
  omp_set_num_threads(saved);
  EXPECT_EQ(one.offset, two.offset);  // exact: the order is part of the contract (deterministic sums)
  EXPECT_EQ(one.index, two.index);
  // and rebuilding gives the same lists again
  NeighbourList again;
  build_neighbours(p, h, kRadius, again);
  EXPECT_EQ(one.index, again.index);
}

// Verlet lists: lists built 20% wide, then the particles move by less than half the extra reach;
// filtering the wide lists gives exactly the pairs a fresh search finds at the new positions.
TEST(CellList, FilteredWideListsMatchAFreshSearchAfterSmallMoves) {
  for (const auto& c : kClouds) {
    std::vector<double> h;
    Particles p = cloud(c.dim, c.n, box(c.dim, Boundary::Open), c.h0, 41 + c.dim, h);
    std::fill(h.begin(), h.end(), 2.0 * c.h0);  // fixed h, as the Verlet lists require
    NeighbourList wide, filtered, fresh;
    const double skin = 0.2;
    build_neighbours(p, h, kRadius * (1.0 + skin), wide);
    Rng rng{99u + c.dim};
    const double step = 0.49 * skin * kRadius * 2.0 * c.h0;  // just under half the extra reach
    for (std::size_t i = 0; i < p.size(); ++i) {
      double d[3] = {0.0, 0.0, 0.0}, norm = 0.0;
      for (int k = 0; k < c.dim; ++k) { d[k] = rng.uniform() - 0.5; norm += d[k] * d[k]; }
      norm = std::sqrt(norm);
      for (int k = 0; k < c.dim; ++k) p.x[k][i] += norm > 0.0 ? step * d[k] / norm : 0.0;
    }
    filter_neighbours(p, h, kRadius, wide, filtered);
    build_neighbours(p, h, kRadius, fresh);
    ASSERT_EQ(filtered.pairs(), fresh.pairs()) << c.dim << "D";
    EXPECT_GT(wide.pairs(), fresh.pairs());  // the wide lists did hold extra candidates
    for (std::size_t i = 0; i < p.size(); ++i) {
      std::vector<std::uint32_t> a(filtered.of(i).begin(), filtered.of(i).end()), b(fresh.of(i).begin(), fresh.of(i).end());
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      ASSERT_EQ(a, b) << c.dim << "D, particle " << i;
    }
  }
}

}  // namespace
}  // namespace sph
