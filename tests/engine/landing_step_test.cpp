// integrators/landing_step.h: a step towards a target time never leaves a sliver (two equal steps
// instead), a remaining time within rounding of the step is taken whole, and World::step(T - t), as
// `sph run` steps to its outputs, takes the same steps as World::advance_to(T), as the GUI's run B and a
// lesson step to theirs: the same state to the last bit.
#include "integrators/landing_step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sph/config.h"
#include "sph/world.h"

namespace sph {
namespace {

TEST(LandingStep, NoStepIsShorterThanHalfTheFreeOneBeforeATarget) {
  const double dt = 0.004;
  EXPECT_EQ(landing_step(dt, 1.0), dt);                    // far from the target: the free step
  EXPECT_EQ(landing_step(dt, 2.0 * dt), dt);               // two whole steps
  EXPECT_EQ(landing_step(dt, 1.25 * dt), 0.625 * dt);      // a step and a quarter: two of 0.625 dt
  EXPECT_EQ(landing_step(dt, 0.3 * dt), 0.3 * dt);         // the target within one step
  EXPECT_EQ(landing_step(dt, dt * (1.0 + 1e-12)), dt * (1.0 + 1e-12));  // within rounding: whole
  EXPECT_EQ(landing_step(dt, 1e300), dt);                  // no target (World::step's default)
  // stepping to a target from any distance: each step at least half the free one, or the whole rest
  for (double r0 : {0.7 * dt, 1.01 * dt, 1.5 * dt, 1.99 * dt, 7.2 * dt, 25.25 * dt}) {
    double left = r0;
    int steps = 0;
    while (left > 0.0 && steps < 100) {
      const double s = landing_step(dt, left);
      EXPECT_GE(s, std::min(0.5 * dt, left)) << "from " << r0 / dt << " dt, " << left / dt << " dt left";
      EXPECT_LE(s, dt);
      left = left - s <= 1e-15 * r0 ? 0.0 : left - s;
      ++steps;
    }
    EXPECT_EQ(left, 0.0) << r0 / dt;
  }
}

TEST(LandingStep, StepToATargetAndAdvanceToAreTheSameRun) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "60", "test");
  cfg.validate();
  World by_step(cfg), by_advance(cfg);
  int shortened = 0;
  for (int k = 1; k <= 12; ++k) {
    const double target = 1.3e-3 * k;  // not a multiple of the adaptive dt
    while (by_step.time() < target * (1.0 - 1e-14)) {
      const double dt_free = by_step.next_dt(), left = target - by_step.time();
      const double t0 = by_step.time();
      by_step.step(left);
      const double taken = by_step.time() - t0;
      EXPECT_GE(taken, std::min(0.5 * dt_free, left) * (1.0 - 1e-9)) << "target " << k;
      shortened += taken < dt_free * (1.0 - 1e-9);
    }
    by_advance.advance_to(target);
    ASSERT_EQ(by_step.time(), by_advance.time()) << "target " << k;
  }
  EXPECT_GT(shortened, 0);  // the targets did cut steps short
  const auto& a = by_step.particles()[Field::Density];
  const auto& b = by_advance.particles()[Field::Density];
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "particle " << i;
}

}  // namespace
}  // namespace sph
