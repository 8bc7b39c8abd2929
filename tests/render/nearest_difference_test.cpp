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

TEST(NearestDifference, OtherParticlesUseTheNearestAsBruteForceFindsIt) {
  const Snapshot a = random_cloud(2, 500), b = random_cloud(2, 321);
  std::vector<float> va(a.count, 0.f), vb(b.count);
  for (std::size_t j = 0; j < b.count; ++j) vb[j] = static_cast<float>(j);
  const std::vector<float> d = nearest_difference(a, va, b, vb);
  for (std::size_t i = 0; i < a.count; i += 7) {
    std::size_t best = 0;
    float best_d2 = INFINITY;
    for (std::size_t j = 0; j < b.count; ++j) {
      const float d2 = (a.x[i] - b.x[j]) * (a.x[i] - b.x[j]) + (a.y[i] - b.y[j]) * (a.y[i] - b.y[j]);
      if (d2 < best_d2) best_d2 = d2, best = j;
    }
    EXPECT_EQ(d[i], static_cast<float>(best)) << "particle " << i;
  }
  const Snapshot c3 = random_cloud(3, 400), d3 = random_cloud(3, 250);
  std::vector<float> zero(c3.count, 0.f), idx(d3.count);
  for (std::size_t j = 0; j < d3.count; ++j) idx[j] = static_cast<float>(j);
  const std::vector<float> e = nearest_difference(c3, zero, d3, idx);
  for (std::size_t i = 0; i < c3.count; i += 11) {
    std::size_t best = 0;
    float best_d2 = INFINITY;
    for (std::size_t j = 0; j < d3.count; ++j) {
      const float dx = c3.x[i] - d3.x[j], dy = c3.y[i] - d3.y[j], dz = c3.z[i] - d3.z[j];
      if (dx * dx + dy * dy + dz * dz < best_d2) best_d2 = dx * dx + dy * dy + dz * dz, best = j;
    }
    EXPECT_EQ(e[i], static_cast<float>(best)) << "3D particle " << i;
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
