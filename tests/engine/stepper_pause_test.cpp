// The stepper's pause time (Stepper::set_pause_at, a lesson step's "pause_at"): the run pauses with its
// step landing exactly on the time, Play runs on past it to t_end, and a reset run pauses there again.
#include <gtest/gtest.h>

#include "sph/stepper.h"
#include "stepper_wait.h"

namespace sph {
namespace {

using test::wait_for;

TEST(StepperPause, PausesExactlyAtTheTimeThenRunsOnToTheEnd) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  cfg.params.time.t_end = 0.05;
  StepperOptions o;
  o.start_running = false;
  Stepper s(cfg, o);
  s.set_pause_at(0.0123);  // not a multiple of any step
  s.resume();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.running && f.snapshot.t > 0.0; }));
  EXPECT_NEAR(s.latest()->snapshot.t, 0.0123, 1e-12);
  EXPECT_FALSE(s.latest()->at_end);
  s.resume();  // on past the pause, to t_end
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.at_end; }));
  EXPECT_NEAR(s.latest()->snapshot.t, 0.05, 1e-12);
  s.reset(cfg.params);  // from t = 0 again: the pause holds once more
  s.resume();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 2 && !f.running && f.snapshot.t > 0.0; }));
  EXPECT_NEAR(s.latest()->snapshot.t, 0.0123, 1e-12);
  s.set_pause_at(0.0);  // cleared: runs to the end
  s.resume();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 2 && f.at_end; }));
}

}  // namespace
}  // namespace sph
