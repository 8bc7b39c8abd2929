// Report::tree_cells, the tree overlay's data: the walk of one particle of a scene with tree gravity
// covers all the mass, follows gravity.theta (a smaller theta opens more cells), and is empty for a
// scene without the tree or a particle out of range.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/world.h"

namespace sph {
namespace {

std::size_t whole(const std::vector<TreeCell>& cells) {
  std::size_t n = 0;
  for (const TreeCell& c : cells) n += c.whole ? 1 : 0;
  return n;
}

TEST(WorldTreeProbe, ThePickedParticlesWalkFollowsTheta) {
  RunConfig cfg = RunConfig::from_scene("dust_sphere");
  cfg.set("scene.n", "2000", "test");
  World w(cfg);
  const auto coarse = w.report().tree_cells(5);
  ASSERT_FALSE(coarse.empty());
  EXPECT_GT(whole(coarse), 0u);
  EXPECT_LT(coarse.size(), 2000u);  // far fewer terms than particles
  const Snapshot s = w.report().snapshot();
  // the probed particle lies in one of its own leaves (the walk always opens the cells around it)
  bool inside = false;
  for (const TreeCell& c : coarse)
    if (!c.whole && std::abs(s.x[5] - c.center[0]) <= c.half * 1.0001f &&
        std::abs(s.y[5] - c.center[1]) <= c.half * 1.0001f && std::abs(s.z[5] - c.center[2]) <= c.half * 1.0001f)
      inside = true;
  EXPECT_TRUE(inside);
  Params fine = w.params();
  fine.gravity.theta = 0.3;
  w.set_params(fine);
  EXPECT_GT(w.report().tree_cells(5).size(), coarse.size());
}

TEST(WorldTreeProbe, EmptyWithoutTheTreeOrOutOfRange) {
  RunConfig cfg = RunConfig::from_scene("dust_sphere");
  cfg.set("scene.n", "500", "test");
  EXPECT_TRUE(World(cfg).report().tree_cells(500).empty());
  cfg.set("physics.gravity", "direct", "test");
  EXPECT_TRUE(World(cfg).report().tree_cells(0).empty());
  EXPECT_TRUE(World(RunConfig::from_scene("sod")).report().tree_cells(0).empty());
}

}  // namespace
}  // namespace sph
