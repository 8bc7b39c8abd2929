// Lists gathered row by row from a kept grid (cell_list_rows.cpp): whatever the batches, whenever they
// are gathered (the particles having moved since the grid was built) and across a reordering of the
// particles, every list equals the one build_neighbours gave at the build, entry for entry; on one
// thread and on a team.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "sph/domain.h"
#include "sph/neighbours.h"

namespace sph {
namespace {

constexpr double kRadius = 2.3;  // M4 support with a skin, in units of h

/// n particles in a periodic unit square with ghosts; h varies by a factor 3 (same cloud every run).
Particles cloud(std::size_t n, std::vector<double>& h, Domain& d) {
  d.lo = {0, 0, 0};
  d.hi = {1, 1, 1};
  d.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  Particles p(2, n, FieldSet{});
  std::uint64_t s = 12345;
  auto u = [&s] {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.x[0][i] = u();
    p.x[1][i] = u();
    h[i] = 0.01 * std::pow(3.0, u());
  }
  make_ghosts(d, kRadius * 0.03, p);
  h.resize(p.total());
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) h[n + g] = h[p.ghost_src[g]];
  return p;
}

std::vector<std::uint32_t> row(const NeighbourList& nl, std::size_t i) {
  const auto r = nl.of(i);
  return {r.begin(), r.end()};
}

/// Gathers the rows in three interleaved batches after the particles moved, and compares with `full`.
void check_batches(int threads) {
  omp_set_num_threads(threads);
  Domain d;
  std::vector<double> h;
  Particles p = cloud(6000, h, d);
  const std::size_t n = p.size();
  NeighbourList full, rows;
  build_neighbours(p, h, kRadius, full);
  build_neighbour_grid(p, h, kRadius, rows);
  const std::array<std::vector<double>, 3> built = {p.x[0], p.x[1], p.x[2]};
  for (std::size_t i = 0; i < n; ++i) p.x[0][i] += 0.003;  // gathering later must use the build's positions
  EXPECT_EQ(rows.pairs(), 0u);
  for (std::size_t batch : {1u, 2u, 0u}) {
    std::vector<std::uint32_t> want;
    for (std::size_t i = batch; i < n; i += 3) want.push_back(static_cast<std::uint32_t>(i));
    gather_neighbour_rows(built, h, kRadius, want, rows);
    for (std::size_t i = 0; i < n; i += 97) {  // the rows not asked for yet stay empty
      const bool pending = i % 3 != batch && (batch == 1 || (batch == 2 && i % 3 == 0));
      if (pending) {
        EXPECT_TRUE(rows.of(i).empty()) << i;
      }
    }
  }
  ASSERT_EQ(rows.pairs(), full.pairs());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(row(rows, i), row(full, i)) << "particle " << i;
  omp_set_num_threads(2);
}

TEST(CellListRows, BatchesEqualTheWholeBuildOnOneThread) { check_batches(1); }
TEST(CellListRows, BatchesEqualTheWholeBuildOnATeam) { check_batches(2); }

TEST(CellListRows, RowsGatheredAfterAReorderingComeRenumbered) {
  Domain d;
  std::vector<double> h;
  const Particles p = cloud(3000, h, d);
  const std::size_t n = p.size();
  NeighbourList full, rows;
  build_neighbours(p, h, kRadius, full);
  build_neighbour_grid(p, h, kRadius, rows);
  std::array<std::vector<double>, 3> built = {p.x[0], p.x[1], p.x[2]};
  std::vector<std::uint32_t> first(n / 2);
  std::iota(first.begin(), first.end(), 0u);
  gather_neighbour_rows(built, h, kRadius, first, rows);
  std::vector<std::uint32_t> order(n);  // reversed: new slot k holds old particle n-1-k
  for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(n - 1 - k);
  permute_neighbours(full, order);
  permute_neighbours(rows, order);
  std::vector<double> hp(h);
  for (std::size_t k = 0; k < n; ++k) hp[k] = h[order[k]];
  for (auto& x : built) {
    const std::vector<double> old = x;
    for (std::size_t k = 0; k < n; ++k) x[k] = old[order[k]];
  }
  std::vector<std::uint32_t> rest;  // the old second half: now the first slots
  for (std::size_t k = 0; k < n - n / 2; ++k) rest.push_back(static_cast<std::uint32_t>(k));
  gather_neighbour_rows(built, hp, kRadius, rest, rows);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(row(rows, i), row(full, i)) << "particle " << i;
}

}  // namespace
}  // namespace sph
