// Run B of the GUI's A/B comparison (stepper/compare_run.h): a B that crawls (a collapsing or tiny time
// step) no longer holds the engine thread past a stop, so the program quits (the soak test hung in
// ~Stepper, B stepping towards A's time in one call); and World::advance_to stops between steps when asked.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "sph/stepper.h"
#include "sph/world.h"

namespace sph {
namespace {

using Clock = std::chrono::steady_clock;

TEST(CompareRun, AStopInterruptsACrawlingRunB) {
  // B at dt = 1e-12 needs about 1e8 steps to follow one of A's steps (about 1e-4): minutes of work
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  StepperOptions opt;
  opt.start_running = true;
  auto s = std::make_unique<Stepper>(cfg, opt);
  s->set_compare({"time.dt=1e-12"});
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // B is deep in its catching up
  const auto t0 = Clock::now();
  s.reset();  // the destructor stops the engine thread and joins it
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("stepper with a crawling run B stopped in %.3f s\n", seconds);
  EXPECT_LT(seconds, 20.0);  // it took the whole catching up (minutes) before; a step of B is microseconds
}

TEST(CompareRun, ARunBThatCannotKeepUpEndsTheComparisonSayingSo) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  StepperOptions opt;
  opt.start_running = true;
  cfg.params.time.t_end = 1e3;  // A is not stopped by its end while the test watches it go on
  opt.compare_budget = 0.3;  // [s]; 10 s in the GUI
  Stepper s(cfg, opt);
  s.set_compare({"time.dt=1e-12"});
  const auto end = Clock::now() + std::chrono::seconds(60);
  const StepperFrame* f = nullptr;
  while (Clock::now() < end) {
    f = s.latest();
    if (f && f->error.find("cannot keep up") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(f);
  EXPECT_NE(f->error.find("run B (time.dt=1e-12) cannot keep up"), std::string::npos) << f->error;
  EXPECT_FALSE(f->comparing);  // A goes on alone
  const std::int64_t step = f->snapshot.step;
  const auto later = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < later && s.latest()->snapshot.step == step) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_GT(s.latest()->snapshot.step, step);
}

TEST(CompareRun, AdvanceToStopsBetweenStepsWhenAsked) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "40", "test");
  World w(cfg), whole(cfg);
  int asked = 0;
  EXPECT_FALSE(w.advance_to(0.05, [&] { return ++asked > 5; }));  // five steps, then stop
  EXPECT_EQ(w.steps(), 5);
  EXPECT_LT(w.time(), 0.05);
  EXPECT_TRUE(w.advance_to(0.05));  // goes on from there
  EXPECT_TRUE(whole.advance_to(0.05));
  EXPECT_EQ(w.time(), 0.05);
  EXPECT_EQ(w.steps(), whole.steps());  // the same steps as without the stop
  EXPECT_EQ(w.particles().x[0], whole.particles().x[0]);
}

}  // namespace
}  // namespace sph
