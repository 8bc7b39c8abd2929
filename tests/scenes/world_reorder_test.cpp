// The World keeps its particles in Morton order (engine/src/world/world.cpp, reorder): the storage order
// changes, the particles do not. Snapshots list particles in id order, ids stay unique, and a run that
// is reordered conserves what it conserved before (mass exactly, momentum to round-off).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sph/world.h"

namespace sph {
namespace {

TEST(WorldReorder, SnapshotsFollowIdsWhateverTheStorageOrder) {
  RunConfig cfg = RunConfig::from_scene("box_random");
  cfg.set("scene.count", "3000", "world_reorder_test");
  World w(cfg);
  for (int s = 0; s < 20; ++s) w.step();  // reordered at construction and at step 16
  const Particles& p = w.particles();
  std::vector<std::int64_t> ids(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(p.size()));
  std::vector<std::int64_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int64_t> expected(p.size());
  std::iota(expected.begin(), expected.end(), std::int64_t{0});
  ASSERT_EQ(sorted, expected) << "every id once";
  EXPECT_NE(ids, expected) << "the storage is spatially sorted, not in id order";
  const Snapshot snap = w.report().snapshot();
  const auto& by_id = w.by_id();
  for (std::size_t k = 0; k < p.size(); ++k) {
    ASSERT_EQ(p.id[by_id[k]], static_cast<std::int64_t>(k));
    EXPECT_EQ(snap.x[k], static_cast<float>(p.x[0][by_id[k]]));
    EXPECT_EQ(snap.y[k], static_cast<float>(p.x[1][by_id[k]]));
  }
}

TEST(WorldReorder, MomentumStaysConservedAcrossReorders) {
  RunConfig cfg = RunConfig::from_scene("box_random");
  cfg.set("scene.count", "2000", "world_reorder_test");
  World w(cfg);
  const Diagnostics d0 = w.report().diagnostics();
  for (int s = 0; s < 50; ++s) w.step();  // three reorders
  const Diagnostics d1 = w.report().diagnostics();
  // a pairwise-antisymmetric force conserves momentum to round-off: |p| << sum m |v|
  double scale = 0.0;
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.size(); ++i) scale += p[Field::Mass][i] * p.vel(i).norm();
  EXPECT_LT(std::abs(d1.P[0] - d0.P[0]), 1e-12 * scale);
  EXPECT_LT(std::abs(d1.P[1] - d0.P[1]), 1e-12 * scale);
}

}  // namespace
}  // namespace sph
