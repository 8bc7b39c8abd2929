// The stepper's save_state / load_state (the GUI's state panel and divergence dialog): a state saved at
// step N and loaded later brings the World back to step N, and stepping on from it gives bitwise the
// positions of a headless World stepped the same number of times; a damaged file keeps the run as it is;
// a state saved at t_end loads stopped there.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>
#include <unistd.h>

#include "sph/checkpoint.h"
#include "sph/stepper.h"
#include "sph/world.h"
#include "stepper_wait.h"

namespace sph {
namespace {

using namespace std::chrono_literals;

using test::wait_for;

TEST(StepperState, AStateSavedAtTheEndLoadsStoppedThere) {
  // it ran on past t_end (sph-gui --load-state of a state saved at the end recorded frames forever)
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "60", "test");
  cfg.params.time.t_end = 0.01;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sph_stepper_end_" + std::to_string(::getpid()) + ".sph")).string();
  Stepper s(cfg, StepperOptions{});
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.at_end; }));
  s.save_state(path);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.notice.empty() || !f.error.empty(); }));
  ASSERT_EQ(s.latest()->error, "");

  Stepper t(cfg, StepperOptions{});  // running when the state arrives
  const Checkpoint ck = read_checkpoint(path);
  t.load_state(path, RunConfig::from_json_text(ck.config_json, path), ck.world);
  ASSERT_TRUE(wait_for(t, [](const StepperFrame& f) { return f.world_serial == 2 && f.at_end; }));
  std::this_thread::sleep_for(200ms);  // long enough for hundreds of steps
  EXPECT_NEAR(t.latest()->snapshot.t, 0.01, 1e-12) << "ran on past t_end";
  EXPECT_FALSE(t.latest()->running);
  std::filesystem::remove(path);
}

TEST(StepperState, SaveAndLoadGiveTheSavedRunBack) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "60", "test");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sph_stepper_state_" + std::to_string(::getpid()) + ".sph")).string();
  StepperOptions o;
  o.start_running = false;
  Stepper s(cfg, o);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.config.scene != nullptr; }));
  for (int k = 0; k < 20; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 20; }));
  s.save_state(path);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.notice.empty() || !f.error.empty(); }));
  ASSERT_EQ(s.latest()->error, "");
  for (int k = 0; k < 5; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 25; }));

  const Checkpoint ck = read_checkpoint(path);
  const RunConfig saved = RunConfig::from_json_text(ck.config_json, path);
  s.load_state(path, saved, ck.world);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 20; }));
  for (int k = 0; k < 10; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 30; }));

  World headless(cfg);
  for (int k = 0; k < 30; ++k) headless.step();
  const Snapshot snap = s.latest()->snapshot;
  const Snapshot want = headless.report().snapshot();
  EXPECT_EQ(snap.t, want.t);
  EXPECT_EQ(snap.x, want.x);  // floats of the same doubles: bitwise the same run

  // a damaged state: the run on screen stays, the error names the file
  std::string bad = ck.world;
  bad.resize(bad.size() / 2);
  s.load_state(path + ".cut", saved, bad);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.error.empty(); }));
  EXPECT_NE(s.latest()->error.find(path + ".cut"), std::string::npos) << s.latest()->error;
  EXPECT_EQ(s.latest()->snapshot.step, 30);
  std::filesystem::remove(path);
}

// Found by the soak test: a state loaded during an A/B comparison restarted run B at t = 0 beside run A at
// the state's time. Run B now starts from the same state, with its overrides, at A's time; an override
// that cannot take the state (another particle count) stops the comparison and says why.
TEST(StepperState, LoadDuringComparisonStartsRunBFromTheState) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "60", "test");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sph_stepper_ab_" + std::to_string(::getpid()) + ".sph")).string();
  StepperOptions o;
  o.start_running = false;
  Stepper s(cfg, o);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.config.scene != nullptr; }));
  for (int k = 0; k < 12; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 12; }));
  s.save_state(path);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.notice.empty(); }));
  const Checkpoint ck = read_checkpoint(path);
  const RunConfig saved = RunConfig::from_json_text(ck.config_json, path);

  s.set_compare({"visc.alpha=0.25"});
  s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.comparing && f.snapshot.step == 1; }));
  s.load_state(path, saved, ck.world);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 12; }));
  const StepperFrame* f = s.latest();
  ASSERT_TRUE(f->comparing);
  EXPECT_EQ(f->compare.snapshot.t, f->snapshot.t);
  EXPECT_EQ(f->compare.snapshot.x, f->snapshot.x);  // the same particles ...
  EXPECT_EQ(f->compare.config.params.visc.alpha, 0.25);  // ... with B's override
  for (int k = 0; k < 5; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.step == 17; }));
  f = s.latest();
  EXPECT_EQ(f->compare.snapshot.t, f->snapshot.t);
  EXPECT_NE(f->compare.snapshot.x, f->snapshot.x);  // another viscosity: another flow from the state on

  s.set_compare({"scene.n_left=30"});  // B with another particle count cannot take A's state
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.comparing && g.snapshot.step == 0; }));
  s.load_state(path, saved, ck.world);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.step == 12; }));
  f = s.latest();
  EXPECT_FALSE(f->comparing);
  EXPECT_NE(f->error.find("comparison stopped"), std::string::npos) << f->error;
  std::filesystem::remove(path);
}

// Found by the soak test: a state saved from a diverged run (the divergence dialog offers "Save state")
// loaded into a World that showed NaN energies as a healthy, paused run. It is now shown diverged at once.
TEST(StepperState, ADivergedStateLoadsAsDiverged) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  cfg.set("time.integrator", "euler", "test");
  cfg.set("time.dt", "10", "test");
  cfg.set("time.t_end", "1e9", "test");  // no end to stop at first
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sph_stepper_nan_" + std::to_string(::getpid()) + ".sph")).string();
  Stepper s(cfg, StepperOptions{});
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.diverged; }));
  s.save_state(path);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.notice.empty(); }));
  s.reset(cfg.params);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 2; }));
  const Checkpoint ck = read_checkpoint(path);
  s.load_state(path, RunConfig::from_json_text(ck.config_json, path), ck.world);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 3; }));
  const StepperFrame* f = s.latest();
  EXPECT_TRUE(f->diverged);
  EXPECT_FALSE(f->running);
  EXPECT_NE(f->error.find("the loaded state"), std::string::npos) << f->error;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace sph
