// The stepper's save_state / load_state (the GUI's state panel and divergence dialog): a state saved at
// step N and loaded later brings the World back to step N, and stepping on from it gives bitwise the
// positions of a headless World stepped the same number of times; a damaged file keeps the run as it is.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>
#include <unistd.h>

#include "sph/checkpoint.h"
#include "sph/stepper.h"
#include "sph/world.h"

namespace sph {
namespace {

using namespace std::chrono_literals;

bool wait_for(Stepper& s, const std::function<bool(const StepperFrame&)>& pred) {
  const auto end = std::chrono::steady_clock::now() + 20s;
  while (std::chrono::steady_clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f && pred(*f)) return true;
    std::this_thread::sleep_for(1ms);
  }
  return false;
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
  const Snapshot want = headless.snapshot();
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

}  // namespace
}  // namespace sph
