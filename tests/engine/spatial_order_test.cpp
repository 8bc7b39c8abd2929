// Spatial ordering (engine/src/core/spatial_order.cpp) and the permutations it drives: the Morton key
// interleaves bits; the order is a permutation that keeps each cell contiguous; permuting particles
// moves every field with its particle and renumbers the ghosts' sources; permuted neighbour lists hold
// exactly the pairs a fresh search finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <vector>

#include "core/spatial_order.h"
#include "sph/domain.h"
#include "sph/neighbours.h"

namespace sph {
namespace {

Particles random_cloud(int dim, std::size_t n, unsigned seed) {
  Particles p(dim, n, FieldSet{}.add(Field::H).add(Field::Density));
  std::uint64_t s = seed;
  auto uniform = [&] {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) p.x[k][i] = uniform();
    p[Field::H][i] = 0.05 + 0.02 * uniform();
    p[Field::Density][i] = 1.0 + i;  // marks the particle
  }
  return p;
}

TEST(SpatialOrder, MortonKeyInterleavesBits) {
  const std::uint32_t a[3] = {1, 0, 0}, b[3] = {0, 1, 0}, c[3] = {3, 1, 0}, d[3] = {1, 1, 1};
  EXPECT_EQ(morton_key(a, 2), 1u);
  EXPECT_EQ(morton_key(b, 2), 2u);
  EXPECT_EQ(morton_key(c, 2), 0b0111u);  // x = 11, y = 01 -> y1 x1 y0 x0 = 0 1 1 1
  EXPECT_EQ(morton_key(d, 3), 0b111u);
  EXPECT_EQ(morton_key(c, 1), 3u);  // 1D: the coordinate itself
}

TEST(SpatialOrder, IsAPermutationWithContiguousCells) {
  for (int dim : {1, 2, 3}) {
    const Particles p = random_cloud(dim, 3000, 7u + dim);
    const double cell = 0.1;
    const std::vector<std::uint32_t> order = morton_order(p, 0, p.size(), cell);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> identity(p.size());
    std::iota(identity.begin(), identity.end(), 0u);
    ASSERT_EQ(sorted, identity) << "dim " << dim;
    // each cell's particles form one run in the new order, and inside a cell the old order is kept;
    // cells are counted from the lowest coordinate on each axis
    double lo[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < dim; ++k) lo[k] = *std::min_element(p.x[k].begin(), p.x[k].end());
    auto cell_of = [&](std::uint32_t i) {
      std::uint32_t c[3] = {0, 0, 0};
      for (int k = 0; k < dim; ++k) c[k] = static_cast<std::uint32_t>(std::floor((p.x[k][i] - lo[k]) / cell));
      return morton_key(c, dim);
    };
    std::set<std::uint64_t> closed;
    for (std::size_t k = 1; k < order.size(); ++k) {
      const auto prev = cell_of(order[k - 1]), now = cell_of(order[k]);
      if (now == prev) {
        EXPECT_LT(order[k - 1], order[k]);
      } else {
        EXPECT_LT(prev, now);
        EXPECT_TRUE(closed.insert(prev).second) << "cell visited twice, dim " << dim;
      }
    }
  }
}

TEST(SpatialOrder, PermuteMovesEveryFieldAndRenumbersGhostSources) {
  Particles p = random_cloud(2, 500, 3u);
  Domain d;
  for (int k = 0; k < 2; ++k) { d.lo[k] = 0.0; d.hi[k] = 1.0; d.bc[k] = Boundary::Periodic; }
  make_ghosts(d, 0.15, p);
  ASSERT_GT(p.ghost_src.size(), 0u);
  const Particles before = p;
  const std::vector<std::uint32_t> order = morton_order(p, 0, p.size(), 0.1);
  p.permute(order);
  ASSERT_EQ(p.total(), before.total());
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t i = order[k];
    EXPECT_EQ(p.id[k], before.id[i]);
    EXPECT_EQ(p.x[0][k], before.x[0][i]);
    EXPECT_EQ(p.x[1][k], before.x[1][i]);
    EXPECT_EQ(p[Field::Density][k], before[Field::Density][i]);
    EXPECT_EQ(p[Field::H][k], before[Field::H][i]);
  }
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) {
    EXPECT_EQ(p.id[p.ghost_src[g]], before.id[before.ghost_src[g]]);  // the same source particle
    EXPECT_EQ(p.x[0][p.size() + g], before.x[0][before.size() + g]);  // the ghost itself is unchanged
  }
}

TEST(SpatialOrder, PermutedListsHoldTheSamePairsAsAFreshSearch) {
  Particles p = random_cloud(2, 800, 11u);
  Domain d;
  for (int k = 0; k < 2; ++k) { d.lo[k] = 0.0; d.hi[k] = 1.0; d.bc[k] = Boundary::Periodic; }
  make_ghosts(d, 0.3, p);
  std::vector<double> h(p.total());
  for (std::size_t i = 0; i < p.size(); ++i) h[i] = p[Field::H][i];
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) h[p.size() + g] = h[p.ghost_src[g]];
  NeighbourList nl;
  build_neighbours(p, h, 2.0, nl);
  const std::vector<std::uint32_t> order = morton_order(p, 0, p.size(), 0.15);
  p.permute(order);
  for (std::size_t k = 0; k < p.size(); ++k) h[k] = p[Field::H][k];
  permute_neighbours(nl, order);
  NeighbourList fresh;
  build_neighbours(p, h, 2.0, fresh);
  ASSERT_EQ(nl.pairs(), fresh.pairs());
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::vector<std::uint32_t> a(nl.of(k).begin(), nl.of(k).end()), b(fresh.of(k).begin(), fresh.of(k).end());
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    ASSERT_EQ(a, b) << "particle " << k;
  }
}

}  // namespace
}  // namespace sph
