// The difference map's values (nearest_difference.cpp): B's value at the nearest B particle minus A's
// own, exactly the difference where both runs have the same particles, the nearest one where they do
// not (brute force), and NaN at walls.
#include <gtest/gtest.h>

#include <cmath>

#include "nearest_difference.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

TEST(NearestDifference, SameParticlesGiveTheDifference) {
  const Snapshot a = lattice_2d(20, 10);
  std::vector<float> va(a.count), vb(a.count);
  for (std::size_t i = 0; i < a.count; ++i) va[i] = 1.f, vb[i] = 1.f + a.y[i];
  const std::vector<float> d = nearest_difference(a, va, a, vb);
  for (std::size_t i = 0; i < a.count; ++i) EXPECT_FLOAT_EQ(d[i], (1.f + a.y[i]) - 1.f);
}

/// Index of the particle of b nearest to particle i of a, by brute force.
std::size_t brute_nearest(const Snapshot& a, std::size_t i, const Snapshot& b) {
  std::size_t best = 0;
  float best_d2 = INFINITY;
  for (std::size_t j = 0; j < b.count; ++j) {
    const float dx = a.x[i] - b.x[j], dy = a.y[i] - b.y[j], dz = a.z[i] - b.z[j];
    if (dx * dx + dy * dy + dz * dz < best_d2) best_d2 = dx * dx + dy * dy + dz * dz, best = j;
  }
  return best;
}

TEST(NearestDifference, OtherParticlesUseTheNearestAsBruteForceFindsIt) {
  for (int dim : {2, 3}) {
    const Snapshot a = random_cloud(dim, 500), b = random_cloud(dim, 321);
    std::vector<float> va(a.count, 0.f), vb(b.count);
    for (std::size_t j = 0; j < b.count; ++j) vb[j] = static_cast<float>(j);  // B's value: its index
    const std::vector<float> d = nearest_difference(a, va, b, vb);
    for (std::size_t i = 0; i < a.count; i += 7)
      EXPECT_EQ(d[i], static_cast<float>(brute_nearest(a, i, b))) << dim << "D particle " << i;
  }
}

TEST(NearestDifference, WallsAreNaN) {
  const Snapshot t = tank_2d(12, 8);
  std::vector<float> v(t.count, 1.f);
  const std::vector<float> d = nearest_difference(t, v, t, v);
  for (std::size_t i = 0; i < t.count; ++i) {
    if (t.is_wall(i)) EXPECT_TRUE(std::isnan(d[i]));
    else EXPECT_EQ(d[i], 0.f);
  }
}

}  // namespace
}  // namespace sph::render::test
