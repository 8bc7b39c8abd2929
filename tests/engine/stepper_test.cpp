// The threaded stepper (sph/stepper.h): its three channels under stress, with a reader on another
// thread checking that every frame is consistent (count, step, time and params belong together), that
// step and time never go back within one World, that posted params are adopted, and the commands
// (pause, single step, stop at t_end, real-time factor, recording, divergence) do what they say.
// Also built with ThreadSanitizer (tests/app/CMakeLists.txt: stepper_tsan_test).
#include "sph/stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "sph/world.h"

namespace sph {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

/// Sanitizer builds run ~10x slower: scale the time limits.
#if defined(__SANITIZE_THREAD__)
constexpr int kSlow = 10;
#else
constexpr int kSlow = 1;
#endif

StepperOptions options(bool start_running = true) {
  StepperOptions o;
  o.start_running = start_running;
  return o;
}

RunConfig small_sod(int n_left = 40) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", std::to_string(n_left), "test");
  return cfg;
}

/// The params posted as mailbox version v: every field derived from v, so a frame's params can be
/// checked against its params_version. dt_out is not used by World::step and carries v itself.
Params params_for(std::uint64_t v, const Params& base) {
  static constexpr KernelType kernels[] = {KernelType::M4, KernelType::M5, KernelType::M6,
                                           KernelType::WendlandC2, KernelType::WendlandC4, KernelType::Gaussian};
  static constexpr IntegratorType integrators[] = {IntegratorType::Leapfrog, IntegratorType::RK4,
                                                   IntegratorType::PredictorCorrector};
  Params p = base;
  p.kernel.type = kernels[v % 6];
  p.time.integrator = integrators[(v / 6) % 3];
  p.kernel.eta = (v % 5 == 0) ? 0.0 : 1.1 + 0.05 * static_cast<double>(v % 4);
  p.visc.alpha = 0.5 + 0.1 * static_cast<double>(v % 7);
  p.visc.beta = 2.0 * p.visc.alpha;
  p.time.cfl = 0.1 + 0.02 * static_cast<double>(v % 9);
  p.time.t_end = 1e9;
  p.time.dt_out = static_cast<double>(v);
  return p;
}

bool same(const Params& a, const Params& b) { return a == b; }

/// Polls latest() until pred holds (true) or the timeout passes (false).
bool wait_for(Stepper& s, const std::function<bool(const StepperFrame&)>& pred,
              std::chrono::milliseconds timeout = 5000ms) {
  const auto end = Clock::now() + timeout * kSlow;
  while (Clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f && pred(*f)) return true;
    std::this_thread::sleep_for(200us);
  }
  return false;
}

/// Checks one frame on its own and against the previous frames; keeps the first problem.
class FrameChecker {
 public:
  explicit FrameChecker(const Params& base) : base_(base) {}

  void check(const StepperFrame& f) {
    const Snapshot& s = f.snapshot;
    if (f.serial <= serial_) fail(f, "serial did not increase");
    if (f.world_serial < world_) fail(f, "world_serial went back");
    if (f.params_version < version_) fail(f, "params_version went back");
    if (s.count != s.x.size() || s.count != s.y.size() || s.count != s.z.size() || s.count != s.h.size())
      fail(f, "count != array sizes");
    for (const auto& fld : s.fields)
      if (fld.values.size() != s.count) fail(f, "field " + fld.name + " has the wrong length");
    if (f.diagnostics.step != s.step || f.diagnostics.t != s.t) fail(f, "diagnostics from another step");
    if (f.ref_values.size() != f.ref_columns.size()) fail(f, "reference values do not match their columns");
    if (!f.history.empty() && f.history.back().ref.size() != f.ref_columns.size())
      fail(f, "history of another reference");
    if (!f.history.empty() && f.history.back().t > s.t) fail(f, "history ahead of the snapshot");
    if (f.config.scene == nullptr || f.config.scene->name != s.scene) fail(f, "config of another scene");
    if (f.params_version > 0 && !same(f.config.params, params_for(f.params_version, base_)))
      fail(f, "params do not match params_version " + std::to_string(f.params_version));
    if (f.comparing) {  // run B: at A's time, with A's params but its override (visc.alpha = 0.25)
      if (f.compare.snapshot.t != s.t) fail(f, "run B at another time");
      Params b = f.config.params;
      b.visc.alpha = 0.25;
      if (!same(f.compare.config.params, b)) fail(f, "run B's params are not A's with its override");
      if (f.compare.history.size() != f.history.size()) fail(f, "run B's history is not sampled with A's");
    }
    if (f.world_serial == world_) {
      if (s.step < step_ || s.t < t_) fail(f, "step or time went back within one World");
      if (s.count != count_) fail(f, "particle count changed within one World");
    }
    serial_ = f.serial;
    world_ = f.world_serial;
    version_ = f.params_version;
    step_ = s.step;
    t_ = s.t;
    count_ = s.count;
    ++frames_;
  }
  std::uint64_t frames() const { return frames_; }
  std::uint64_t failures() const { return failures_; }
  const std::string& first_failure() const { return first_; }

 private:
  void fail(const StepperFrame& f, const std::string& what) {
    if (failures_++ == 0) first_ = what + " (frame " + std::to_string(f.serial) + ")";
  }
  Params base_;
  std::uint64_t serial_ = 0, world_ = 0, version_ = 0, frames_ = 0, failures_ = 0;
  std::int64_t step_ = 0;
  double t_ = 0.0;
  std::size_t count_ = 0;
  std::string first_;
};

TEST(Stepper, FirstFrameHoldsTheBuiltScene) {
  const RunConfig cfg = small_sod();
  Stepper s(cfg, options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  const StepperFrame* f = s.latest();
  EXPECT_EQ(f->world_serial, 1u);
  EXPECT_EQ(f->snapshot.scene, "sod");
  EXPECT_GT(f->snapshot.count, 40u);
  EXPECT_EQ(f->snapshot.step, 0);
  EXPECT_FALSE(f->running);
  EXPECT_TRUE(f->has_reference);
  EXPECT_EQ(f->params_version, 1u);
}

// The stress test: thousands of params posts and commands while the engine steps and another thread
// reads every frame it can.
TEST(Stepper, StressParamsAndCommandsKeepFramesConsistent) {
  RunConfig cfg = small_sod();
  const Params base = cfg.params;
  std::uint64_t version = 1;  // the constructor's load posts version 1
  cfg.params = params_for(version, base);
  Stepper s(cfg, options());

  std::atomic<bool> stop{false};
  std::atomic<std::uint64_t> seen{0};  // frames the reader has checked
  FrameChecker checker(base);
  std::thread reader([&] {
    std::uint64_t last = 0;
    while (!stop.load()) {
      if (const StepperFrame* f = s.latest()) {
        if (f->serial != last) {
          checker.check(*f);
          ++seen;
        }
        last = f->serial;
      }
      std::this_thread::sleep_for(100us);  // a busy reader on a full machine would starve the engine
    }
  });

  // 3000 posts of every kind, then parameter posts only until the reader has checked 100 frames: on a
  // loaded machine (TSan, other jobs) the rebuilds every 50 posts kept the engine from publishing any
  // frame, and the test ran into ctest's timeout. The deadline stays well below that timeout.
  const auto deadline = Clock::now() + 30s * kSlow;
  for (int i = 0; i < 3000; ++i) {
    switch (i % 50) {
      case 10: s.pause(); break;
      case 11: s.step_once(); break;
      case 12: s.step_once(); break;
      case 13: s.resume(); break;
      case 20: EXPECT_EQ(s.reset(params_for(version + 1, base)), version + 1); ++version; break;
      case 25: s.set_stop_at_end(i % 100 == 25); break;
      case 30: s.set_scene_value("n_left", 30 + 5 * (i % 3)); break;
      case 35: s.set_real_time_factor(i % 100 == 35 ? 100.0 : 0.0); break;
      case 40: s.set_compare(i % 100 == 40 ? std::vector<std::string>{"visc.alpha=0.25"} : std::vector<std::string>{}); break;
      case 45: {
        RunConfig next = RunConfig::from_scene(i % 100 == 45 ? "shocktube_castellanos" : "sod");
        next.set("scene.n_left", "30", "test");
        next.params = params_for(++version, base);
        EXPECT_EQ(s.load(next), version);
        break;
      }
      default:
        EXPECT_EQ(s.post_params(params_for(++version, base)), version);
    }
    std::this_thread::sleep_for(200us);  // let the engine step between posts
  }
  s.set_stop_at_end(false);
  s.set_real_time_factor(0.0);
  s.resume();
  while (seen.load() < 100 && Clock::now() < deadline) {
    EXPECT_EQ(s.post_params(params_for(++version, base)), version);
    std::this_thread::sleep_for(2ms);
  }
  stop = true;
  reader.join();  // latest() has one reader at a time: from here on, this thread
  EXPECT_EQ(checker.failures(), 0u) << checker.first_failure();
  EXPECT_GE(checker.frames(), 100u);

  // The last post is adopted and the engine keeps stepping with it.
  s.set_real_time_factor(0.0);
  s.resume();
  const std::uint64_t last = s.post_params(params_for(++version, base));
  EXPECT_TRUE(wait_for(s, [&](const StepperFrame& f) { return f.params_version == last; }));
  std::int64_t step0 = -1;
  EXPECT_TRUE(wait_for(s, [&](const StepperFrame& f) {
    if (f.params_version != last || f.diverged) return false;
    if (step0 < 0) step0 = f.snapshot.step;
    return f.snapshot.step > step0 + 5;
  }));
  const StepperFrame* f = s.latest();
  ASSERT_NE(f, nullptr);
  EXPECT_TRUE(same(f->config.params, params_for(last, base)));
}

TEST(Stepper, PauseHoldsAndSingleStepAdvancesOneStep) {
  // t_end far away: on a loaded machine the engine ran Sod's 62 steps to t = 0.2 before the pause
  // landed, and the single steps queued past t_end stopped there (the next test) instead of counting 3
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 1e3;
  Stepper s(cfg, options());
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step > 3; }));
  s.pause();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.running; }));
  const std::int64_t held = s.latest()->snapshot.step;
  std::this_thread::sleep_for(30ms);
  EXPECT_EQ(s.latest()->snapshot.step, held);
  for (int k = 0; k < 3; ++k) s.step_once();
  EXPECT_TRUE(wait_for(s, [&](const StepperFrame& f) { return f.snapshot.step == held + 3; }));
  std::this_thread::sleep_for(30ms);
  EXPECT_EQ(s.latest()->snapshot.step, held + 3);
  EXPECT_FALSE(s.latest()->running);
}

TEST(Stepper, SingleStepsQueuedPastTheEndStopAtTheEnd) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.02;
  Stepper s(cfg, options());
  s.pause();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.running; }));
  for (int k = 0; k < 100; ++k) s.step_once();  // more than the steps to t_end
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.at_end; }));
  std::this_thread::sleep_for(30ms);
  EXPECT_NEAR(s.latest()->snapshot.t, 0.02, 1e-12) << "single steps ran on past t_end";
  EXPECT_FALSE(s.latest()->running);
}

TEST(Stepper, StopsExactlyAtEndTime) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.02;
  Stepper s(cfg, options());
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.at_end; }));
  const StepperFrame* f = s.latest();
  EXPECT_FALSE(f->running);
  EXPECT_NEAR(f->snapshot.t, 0.02, 1e-12);
  // Play at t_end with "stop at t_end" on stays at t_end (it ran on to t = 0.77 on sod before)...
  s.resume();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // long enough for hundreds of steps
  EXPECT_NEAR(s.latest()->snapshot.t, 0.02, 1e-12) << "ran on past t_end";
  EXPECT_FALSE(s.latest()->running);
  // ...and runs on once the stop is off.
  s.set_stop_at_end(false);
  s.resume();
  EXPECT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.t > 0.021; }));
}

TEST(Stepper, ResetAfterTheEndRunsAgain) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.01;
  Stepper s(cfg, options());
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.at_end; }));
  s.reset(cfg.params);  // stopped only by t_end: the new World runs (a user's pause would be kept)
  EXPECT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 2 && f.at_end; }));
}

TEST(Stepper, LiveParamsChangeTheRunningWorld) {
  // t_end far away from the start: a busy machine could otherwise let the 40-particle tube reach its
  // own t_end = 0.2 (and stop there) before the params below are adopted
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 1e9;
  Stepper s(cfg, options());
  Params p = RunConfig::from_scene("sod").params;
  p.kernel.type = KernelType::M6;
  p.time.integrator = IntegratorType::RK4;
  p.visc.alpha = 0.3;
  p.kernel.eta = 1.4;
  p.time.t_end = 1e9;
  const std::uint64_t v = s.post_params(p);
  ASSERT_TRUE(wait_for(s, [&](const StepperFrame& f) { return f.params_version == v; }));
  const StepperFrame* f = s.latest();
  EXPECT_EQ(f->config.params.kernel.type, KernelType::M6);
  EXPECT_EQ(f->config.params.time.integrator, IntegratorType::RK4);
  EXPECT_EQ(f->config.params.visc.alpha, 0.3);
  EXPECT_EQ(f->world_serial, 1u);  // no rebuild: the same World keeps stepping
  const std::int64_t step = f->snapshot.step;
  EXPECT_TRUE(wait_for(s, [&](const StepperFrame& g) { return g.snapshot.step > step + 2; }));
}

TEST(Stepper, SceneValueRebuildsTheWorld) {
  Stepper s(small_sod(40), options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  const std::size_t n40 = s.latest()->snapshot.count;
  s.set_scene_value("n_left", 80);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.world_serial == 2; }));
  EXPECT_GT(s.latest()->snapshot.count, n40);
  EXPECT_EQ(s.latest()->config.values.at("n_left"), 80.0);
  s.set_scene_value("n_left", -5);  // out of range: reported, World kept
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return !f.error.empty(); }));
  EXPECT_EQ(s.latest()->world_serial, 2u);
}

TEST(Stepper, RealTimeFactorPacesSimulatedTime) {
  Stepper s(small_sod(), options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  const double rtf = 0.02;  // simulated seconds per wall second
  s.set_real_time_factor(rtf);
  s.resume();
  const auto t0 = Clock::now();
  std::this_thread::sleep_for(400ms);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.running; }));
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const StepperFrame* f = s.latest();
  EXPECT_EQ(f->real_time_factor, rtf);
  EXPECT_LE(f->snapshot.t, rtf * wall + 2.0 * f->snapshot.dt);  // never ahead of the wall clock (but a step)
  EXPECT_GT(f->snapshot.t, 0.25 * rtf * wall);
}

// Recording: every frame lands on t0 + k every, and none is lost even with a slow reader.
TEST(Stepper, RecordingDeliversEveryFrameAtFixedTimes) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.05;
  Stepper s(cfg, options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  const double every = 0.01;
  s.set_record_interval(every);
  s.resume();
  std::map<int, double> frames;
  const auto end = Clock::now() + 10s * kSlow;
  while (Clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f->record_index >= 0) frames[f->record_index] = f->snapshot.t;
    if (f->at_end && frames.size() == 6) break;
    std::this_thread::sleep_for(3ms);  // slower than the engine
  }
  ASSERT_EQ(frames.size(), 6u);  // t = 0, 0.01, ..., 0.05
  for (const auto& [k, t] : frames) EXPECT_NEAR(t, k * every, 1e-12) << "frame " << k;
}

// Recording does not shorten steps longer than the frame interval (it forced dt <= every for every
// scene: box_perturbed fell to 9.8 steps/s); each step that reaches a frame time is recorded instead.
TEST(Stepper, RecordingKeepsStepsLongerThanTheInterval) {
  RunConfig cfg = small_sod();
  cfg.params.time.dt = 1e-3;  // fixed, ten frame intervals
  Stepper s(cfg, options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  s.set_record_interval(1e-4);
  int recorded = 0;
  for (int k = 1; k <= 5; ++k) {
    s.step_once();
    ASSERT_TRUE(wait_for(s, [k](const StepperFrame& f) { return f.snapshot.step == k; })) << k;
    const StepperFrame* f = s.latest();
    EXPECT_NEAR(f->snapshot.dt, 1e-3, 1e-15) << "step " << k << " was shortened to the frame interval";
    EXPECT_NEAR(f->snapshot.t, k * 1e-3, 1e-12);
    recorded += f->record_index >= 0;
  }
  EXPECT_EQ(recorded, 5);  // every step passed a frame time
}

// Recording from the start (StepperOptions::record_every): frame 0 is t = 0 even though the engine runs
// at once.
TEST(Stepper, RecordingFromTheFirstWorldStartsAtZero) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.03;
  StepperOptions o = options(true);
  o.record_every = 0.01;
  Stepper s(cfg, o);
  std::map<int, double> frames;
  const auto end = Clock::now() + 10s * kSlow;
  while (Clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f && f->record_index >= 0) frames[f->record_index] = f->snapshot.t;
    if (f && f->at_end && frames.size() == 4) break;
    std::this_thread::sleep_for(1ms);
  }
  ASSERT_EQ(frames.size(), 4u);
  for (const auto& [k, t] : frames) EXPECT_NEAR(t, k * 0.01, 1e-12) << "frame " << k;
}

// Divergence: a huge fixed timestep blows the state up; the stepper pauses and says where.
TEST(Stepper, DivergencePausesAndReportsTheParticle) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 1e9;  // still running when the params arrive, however late (a loaded machine)
  Stepper s(cfg, options());
  Params p = cfg.params;
  p.time.dt = 10.0;
  p.time.t_end = 1e9;
  p.time.integrator = IntegratorType::Euler;
  s.post_params(p);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.diverged; }));
  const StepperFrame* f = s.latest();
  EXPECT_FALSE(f->running);
  EXPECT_GE(f->diverged_step, 0);
  EXPECT_NE(f->error.find("diverged"), std::string::npos) << f->error;
  const std::int64_t step = f->snapshot.step;
  s.resume();  // ignored until a reset
  std::this_thread::sleep_for(20ms);
  EXPECT_EQ(s.latest()->snapshot.step, step);
  s.reset(cfg.params);
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.world_serial == 2 && !g.diverged; }));
  EXPECT_TRUE(s.latest()->error.empty());
}

// A/B comparison: both runs restart from t = 0, B with its overrides, and stay at the same times; posted
// params reach both (B keeps its overrides); a refused override changes nothing.
TEST(Stepper, CompareStepsBothRunsToTheSameTimes) {
  RunConfig cfg = small_sod();
  cfg.params.time.t_end = 0.03;
  Stepper s(cfg, options());
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step > 2; }));
  s.set_compare({"kernel.type=M6", "visc.alpha=0"});
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.comparing && f.at_end; }));
  const StepperFrame* f = s.latest();
  EXPECT_EQ(f->world_serial, 2u);  // A restarted with B
  EXPECT_NEAR(f->snapshot.t, 0.03, 1e-12);
  EXPECT_EQ(f->compare.snapshot.t, f->snapshot.t);
  EXPECT_EQ(f->config.params.kernel.type, KernelType::M4);
  EXPECT_EQ(f->compare.config.params.kernel.type, KernelType::M6);
  EXPECT_EQ(f->compare.config.params.visc.alpha, 0.0);
  EXPECT_EQ(f->compare.history.size(), f->history.size());
  EXPECT_EQ(f->compare.ref_values.size(), f->ref_columns.size());
  EXPECT_NE(f->compare.snapshot.x, f->snapshot.x);  // another kernel: another flow
  // a posted edit reaches both; B keeps its overrides
  Params p = f->config.params;
  p.visc.beta = 1.0;
  p.kernel.type = KernelType::M5;
  const std::uint64_t v = s.post_params(p);
  ASSERT_TRUE(wait_for(s, [&](const StepperFrame& g) { return g.params_version == v; }));
  f = s.latest();
  EXPECT_EQ(f->compare.config.params.visc.beta, 1.0);
  EXPECT_EQ(f->compare.config.params.kernel.type, KernelType::M6);
  EXPECT_EQ(f->config.params.kernel.type, KernelType::M5);
  // a refused override: reported, nothing rebuilt
  s.set_compare({"kernel.type=M9"});
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.error.find("M9") != std::string::npos; }));
  f = s.latest();
  EXPECT_EQ(f->world_serial, 2u);
  EXPECT_TRUE(f->comparing);
  s.set_compare({});
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return !g.comparing; }));
}

// The inspector's channel: frames carry Report::inspect of the asked id for the state they show (and of
// run B while comparing).
TEST(Stepper, InspectionFollowsTheState) {
  Stepper s(small_sod(), options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  s.set_inspect(7);
  s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 1 && f.inspection.has_value(); }));
  const StepperFrame* f = s.latest();
  EXPECT_EQ(f->inspection->id, 7);
  EXPECT_EQ(f->inspection->step, 1);
  EXPECT_FLOAT_EQ(static_cast<float>(f->inspection->x.x), f->snapshot.x[7]);
  EXPECT_FALSE(f->inspection->terms.empty());
  s.set_compare({"kernel.type=M6"});
  s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) {
    return g.comparing && g.snapshot.step == 1 && g.inspection && g.compare.inspection && g.inspection->step == 1;
  }));
  f = s.latest();
  EXPECT_EQ(f->compare.inspection->id, 7);
  EXPECT_NE(f->compare.inspection->a_total.x, f->inspection->a_total.x);
  s.set_inspect(-1);
  s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.step == 2 && !g.inspection; }));
}

}  // namespace
}  // namespace sph

namespace sph {
namespace {

/// The user's push through the command queue: the engine thread sets it on its World before the next
/// step and logs it with that step; the frame's log replayed on a World of its own gives the same state
/// (the snapshot's float positions, bit for bit).
TEST(Stepper, PushesAreLoggedAndReplay) {
  RunConfig cfg = RunConfig::from_scene("gresho");
  cfg.set("scene.n_side", "16", "test");
  Stepper s(cfg, options(false));
  ASSERT_TRUE(wait_for(s, [](const StepperFrame&) { return true; }));
  Push push;
  push.x = {0.5, 0.5, 0.0};
  push.v = {1.0, 0.0, 0.0};
  push.radius = 0.2;
  push.tau = 0.05;
  s.set_push(push);
  for (int k = 0; k < 4; ++k) s.step_once();
  // commands are drained together before the steps they ask for: wait for the steps before the release
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 4; }));
  s.set_push(Push{});
  for (int k = 0; k < 3; ++k) s.step_once();
  ASSERT_TRUE(wait_for(s, [](const StepperFrame& f) { return f.snapshot.step == 7; }));
  const StepperFrame& f = *s.latest();
  ASSERT_EQ(f.pushes.size(), 2u);
  EXPECT_EQ(f.pushes[0].step, 0);
  EXPECT_TRUE(f.pushes[0].push == push);
  EXPECT_EQ(f.pushes[1].step, 4);
  EXPECT_FALSE(f.push.active());
  World replay(cfg);
  PushReplay r(f.pushes);
  for (int k = 0; k < 7; ++k) {
    r.apply_due(replay);
    replay.step();
  }
  const Snapshot snap = replay.report().snapshot();
  ASSERT_EQ(snap.count, f.snapshot.count);
  double moved = 0.0;
  for (std::size_t i = 0; i < snap.count; ++i) {
    ASSERT_EQ(snap.x[i], f.snapshot.x[i]) << "particle " << i;
    ASSERT_EQ(snap.y[i], f.snapshot.y[i]) << "particle " << i;
  }
  World unpushed(cfg);
  for (int k = 0; k < 7; ++k) unpushed.step();
  const Snapshot still = unpushed.report().snapshot();
  for (std::size_t i = 0; i < snap.count; ++i) moved = std::max(moved, static_cast<double>(std::abs(snap.x[i] - still.x[i])));
  EXPECT_GT(moved, 1e-4);  // the push did move particles
}

}  // namespace
}  // namespace sph
