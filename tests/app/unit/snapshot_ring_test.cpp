// The scrub ring: keeps the newest frames of one World (one per step), drops the oldest beyond its frame
// count or byte budget, clears on a new World, and stores view-only copies (no history).
#include "snapshot_ring.h"

#include <gtest/gtest.h>

namespace sph::gui {
namespace {

StepperFrame frame(std::uint64_t world, std::int64_t step, std::size_t n = 10) {
  StepperFrame f;
  f.world_serial = world;
  f.serial = static_cast<std::uint64_t>(step) + 1000 * world;
  f.snapshot.step = step;
  f.snapshot.t = 0.01 * static_cast<double>(step);
  f.snapshot.count = n;
  f.snapshot.x.assign(n, 0.f);
  f.snapshot.y.assign(n, 0.f);
  f.snapshot.z.assign(n, 0.f);
  f.snapshot.h.assign(n, 0.f);
  f.history.resize(5);
  return f;
}

TEST(SnapshotRing, KeepsTheNewestFramesOfOneWorld) {
  SnapshotRing r(4, 1 << 20);
  for (int s = 0; s < 6; ++s) r.push(frame(1, s));
  r.push(frame(1, 5));  // the same step again: not stored twice
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r.at(0).snapshot.step, 2);
  EXPECT_EQ(r.at(3).snapshot.step, 5);
  EXPECT_TRUE(r.at(3).history.empty());  // view-only copy
  r.push(frame(2, 0));                   // a new World
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r.at(0).world_serial, 2u);
}

TEST(SnapshotRing, ByteBudgetLimitsLargeFrames) {
  const std::size_t one = SnapshotRing::frame_bytes(frame(1, 0, 1000));
  EXPECT_EQ(one, 4 * 1000 * sizeof(float));
  SnapshotRing r(240, 3 * one);
  for (int s = 0; s < 10; ++s) r.push(frame(1, s, 1000));
  EXPECT_EQ(r.size(), 3u);
  EXPECT_EQ(r.bytes(), 3 * one);
  EXPECT_EQ(r.at(0).snapshot.step, 7);
}

}  // namespace
}  // namespace sph::gui
