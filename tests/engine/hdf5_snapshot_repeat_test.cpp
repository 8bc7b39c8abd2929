// HDF5 snapshots carry no modification times: the same state gives the same bytes whenever it is
// written (a resumed run's files are compared byte for byte with the uninterrupted run's).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "sph/config.h"
#include "sph/ic_export.h"
#include "sph/world.h"

namespace sph {
namespace {

TEST(Hdf5SnapshotRepeat, SameStateSameBytesASecondLater) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  World w(cfg);
  const std::string first = hdf5_snapshot(w, IcFormat::Swift);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // HDF5 object times have 1 s resolution
  EXPECT_TRUE(first == hdf5_snapshot(w, IcFormat::Swift));
}

}  // namespace
}  // namespace sph
