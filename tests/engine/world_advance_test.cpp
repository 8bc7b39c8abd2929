// World::advance_to lands exactly on its target: run B of an A/B comparison is stepped to run A's time
// and must show that time to the last bit, also when A's step was a sliver (A landing on t_end or an
// output time) smaller than the loop's tolerance of 1e-14 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sph/config.h"
#include "sph/world.h"

namespace sph {
namespace {

TEST(WorldAdvance, EveryTargetIsReachedExactly) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "30", "test");
  cfg.set("time.dt", "1e-4", "test");
  cfg.validate();
  World w(cfg);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= 50; ++k) {
    const double target = 7.3e-4 * k;
    w.advance_to(target);
    ASSERT_EQ(w.time(), target) << "target " << k;
    const double sliver = std::nextafter(std::nextafter(target, kInf), kInf);  // two ulps on
    w.advance_to(sliver);
    ASSERT_EQ(w.time(), sliver) << "two ulps past target " << k;
  }
}

}  // namespace
}  // namespace sph
