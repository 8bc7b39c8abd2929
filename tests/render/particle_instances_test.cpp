// The particle pass's instances (app/render/particle_instances.h): a 3D cutaway leaves out the particles
// beyond the plane and keeps each instance's snapshot index (picking and the inspector's highlight).
#include "particle_instances.h"

#include <gtest/gtest.h>

#include "sph/snapshot.h"
#include "synthetic_snapshots.h"

namespace sph::render {
namespace {

TEST(ParticleInstances, CutawayKeepsTheParticlesOnItsSideWithTheirIndices) {
  const Snapshot s = test::ball_3d(500);
  ShownField shown;
  shown.field = s.find("rho");
  std::vector<float> all, cut;
  std::vector<std::uint32_t> index;
  build_instances(s, shown, {Placement::Positions, 0, 0.5f, true}, &all);
  InstanceOptions o{Placement::Positions, 0, 0.5f, true};
  o.cut_axis = 2;
  o.cut_at = 0.1f;
  build_instances(s, shown, o, &cut, &index);
  EXPECT_EQ(all.size(), s.count * kInstanceFloats);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < s.count; ++i) kept += s.z[i] <= 0.1f;
  ASSERT_EQ(index.size(), kept);
  ASSERT_EQ(cut.size(), kept * kInstanceFloats);
  EXPECT_GT(kept, s.count / 4);
  EXPECT_LT(kept, 3 * s.count / 4);
  for (std::size_t k = 0; k < kept; ++k) {
    const std::uint32_t i = index[k];
    EXPECT_LE(s.z[i], 0.1f);
    EXPECT_EQ(cut[k * kInstanceFloats + 0], s.x[i]);  // the instance is that particle's
    EXPECT_EQ(cut[k * kInstanceFloats + 2], s.z[i]);
  }
}

}  // namespace
}  // namespace sph::render
