// Soak test of the threaded stepper (sph/stepper.h), as the GUI drives it: for a bounded wall time
// (SPH_SOAK_SECONDS, default 20), a seeded random mix (SPH_SOAK_SEED, default 1) of parameter edits
// (some wild enough to blow a run up), scene switches, resets, scene-value rebuilds, A/B comparisons,
// inspections, pushes, recordings, pauses, single steps, and state saves and loads, while another thread
// reads every frame it can. Every frame must be self-consistent, and a frame holding a non-finite
// position, smoothing length or field value must say the run diverged: no divergence goes unreported.
// Afterwards a saved state loads back to its step and time, and the engine still steps.
// Built as well with ThreadSanitizer (tests/app/CMakeLists.txt: stepper_soak_tsan) and, in the
// sanitizer build folder, with ASan + UBSan.
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "sph/checkpoint.h"
#include "sph/stepper.h"

namespace sph {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

long env_or(const char* name, long fallback) {
  const char* s = std::getenv(name);
  return s && *s ? std::strtol(s, nullptr, 10) : fallback;
}

/// Small versions of a scene of each method: gas (1D, 2D), liquid, gravity, FPM.
struct SoakScene {
  const char* scene;
  std::vector<std::pair<std::string, std::string>> sets;
  const char* value;  ///< a scene value to rebuild with (set_scene_value)
  double lo, hi;      ///< its range in this test
};

const std::vector<SoakScene>& soak_scenes() {
  static const std::vector<SoakScene> scenes = {
      {"sod", {{"scene.n_left", "40"}}, "n_left", 20, 60},
      {"shocktube_castellanos", {{"scene.n_left", "30"}}, "n_left", 20, 40},
      {"gresho", {{"scene.n_side", "16"}}, "n_side", 12, 20},
      {"dam_break", {{"scene.dx", "0.1"}}, "dx", 0.1, 0.15},
      {"elliptical_drop", {{"scene.dx", "0.1"}}, "dx", 0.1, 0.15},
      {"kepler", {}, "", 0, 0},
      {"evrard", {{"scene.n", "200"}}, "n", 100, 300},
      {"burgers_upwind", {{"scene.n", "100"}}, "n", 50, 150},
  };
  return scenes;
}

RunConfig config_of(const SoakScene& s) {
  RunConfig cfg = RunConfig::from_scene(s.scene);
  for (const auto& [k, v] : s.sets) cfg.set(k, v, "soak");
  cfg.validate();
  return cfg;
}

/// A random edit of the scene's params, as the GUI's widgets make them (time.levels among them: refused
/// where the integrator or a fixed dt cannot take it); one edit in 12 is wild (a huge timestep or CFL
/// number) and may blow the run up, which the stepper must then report.
Params random_edit(const Params& base, std::mt19937_64& rng) {
  static constexpr KernelType kernels[] = {KernelType::M4, KernelType::M5, KernelType::M6,
                                           KernelType::WendlandC2, KernelType::WendlandC4, KernelType::Gaussian};
  static constexpr IntegratorType integrators[] = {IntegratorType::Euler, IntegratorType::Leapfrog,
                                                   IntegratorType::RK4, IntegratorType::PredictorCorrector};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Params p = base;
  switch (rng() % 7) {
    case 0: p.kernel.type = kernels[rng() % 6]; break;
    case 1: p.time.integrator = integrators[rng() % 4]; break;
    case 2: p.visc.alpha = 2.0 * u(rng); p.visc.beta = 2.0 * p.visc.alpha; break;
    case 3: p.time.cfl = 0.05 + 0.35 * u(rng); break;
    case 4: p.kernel.eta = 1.1 + 0.4 * u(rng); break;
    case 5: p.time.levels = 1 + static_cast<int>(rng() % 6); break;  // refused unless leapfrog, adaptive dt
    default: break;  // the same params again
  }
  if (rng() % 12 == 0) {
    p.time.integrator = IntegratorType::Euler;
    p.time.dt = 10.0;  // a fixed step far beyond any stable one
  }
  p.time.t_end = 1e9;  // keep stepping
  return p;
}

bool finite_all(const std::vector<float>& v) {
  for (float x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

/// Checks every frame on its own and against the one before; keeps the first problem.
class SoakChecker {
 public:
  void check(const StepperFrame& f) {
    const Snapshot& s = f.snapshot;
    if (f.serial <= serial_) fail(f, "serial did not increase");
    if (f.world_serial < world_) fail(f, "world_serial went back");
    if (s.count != s.x.size() || s.count != s.y.size() || s.count != s.z.size() || s.count != s.h.size())
      fail(f, "count != array sizes");
    std::string non_finite;  // the first array holding a non-finite value
    if (!finite_all(s.x) || !finite_all(s.y) || !finite_all(s.z)) non_finite = "a position";
    if (non_finite.empty() && !finite_all(s.h)) non_finite = "h";
    for (const auto& fld : s.fields) {
      if (fld.values.size() != s.count) fail(f, "field " + fld.name + " has the wrong length");
      if (non_finite.empty() && !finite_all(fld.values)) {
        non_finite = "field " + fld.name;
        for (float x : fld.values)
          if (!std::isfinite(x)) { non_finite += " (" + std::to_string(x) + ")"; break; }
      }
    }
    if (!non_finite.empty() && !f.diverged)
      fail(f, "a non-finite " + non_finite + " in a frame that does not report a divergence (step " +
                  std::to_string(s.step) + ")");
    if (f.diverged && (f.error.empty() || f.running)) fail(f, "a divergence without its message, or still running");
    if (f.diagnostics.step != s.step || f.diagnostics.t != s.t) fail(f, "diagnostics from another step");
    if (f.ref_values.size() != f.ref_columns.size()) fail(f, "reference values do not match their columns");
    if (!f.history.empty() && f.history.back().t > s.t) fail(f, "history ahead of the snapshot");
    if (f.config.scene == nullptr || f.config.scene->name != s.scene) fail(f, "config of another scene");
    // run B at A's time, unless one of them failed (the frame then says so)
    if (f.comparing && !f.diverged && f.compare.snapshot.t != s.t)
      fail(f, "run B at t = " + std::to_string(f.compare.snapshot.t) + ", run A at " + std::to_string(s.t));
    if (f.inspection && f.inspection->step > s.step) fail(f, "an inspection ahead of the state");
    if (f.world_serial == world_) {
      if (s.step < step_ || s.t < t_) fail(f, "step or time went back within one World");
      if (s.count != count_) fail(f, "particle count changed within one World");
    }
    diverged_ += f.diverged && !was_diverged_;
    was_diverged_ = f.diverged;
    serial_ = f.serial;
    world_ = f.world_serial;
    step_ = s.step;
    t_ = s.t;
    count_ = s.count;
    ++frames_;
  }
  std::uint64_t frames() const { return frames_; }
  std::uint64_t divergences() const { return diverged_; }
  std::uint64_t failures() const { return failures_; }
  const std::string& first_failure() const { return first_; }

 private:
  void fail(const StepperFrame& f, const std::string& what) {
    if (failures_++ == 0) first_ = what + " (frame " + std::to_string(f.serial) + ", scene " + f.snapshot.scene + ")";
  }
  std::uint64_t serial_ = 0, world_ = 0, frames_ = 0, failures_ = 0, diverged_ = 0;
  bool was_diverged_ = false;
  std::int64_t step_ = 0;
  double t_ = 0.0;
  std::size_t count_ = 0;
  std::string first_;
};

/// Polls latest() (this thread must be its only reader) until pred holds or the timeout passes.
template <class Pred>
const StepperFrame* wait_for(Stepper& s, Pred pred, std::chrono::seconds timeout) {
  const auto end = Clock::now() + timeout;
  while (Clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f && pred(*f)) return f;
    std::this_thread::sleep_for(500us);
  }
  return nullptr;
}

/// Loads checkpoint `path` as the GUI does (gui_state_file.cpp); false if it cannot be read yet.
bool load_saved(Stepper& s, const std::string& path) {
  try {
    const Checkpoint ck = read_checkpoint(path);
    RunConfig cfg = RunConfig::from_json_text(ck.config_json, "checkpoint " + path);
    cfg.validate();
    s.load_state(path, cfg, ck.world);
    return true;
  } catch (const std::exception&) {
    return false;  // not written yet, or being replaced right now
  }
}

TEST(StepperSoak, RandomEditsSwitchesAndStateLoadsKeepFramesConsistent) {
  const long seconds = env_or("SPH_SOAK_SECONDS", 20);
  const auto seed = static_cast<std::uint64_t>(env_or("SPH_SOAK_SEED", 1));
  SCOPED_TRACE("SPH_SOAK_SEED=" + std::to_string(seed));
  for (const SoakScene& sc : soak_scenes()) ASSERT_NO_THROW(config_of(sc)) << sc.scene;
  const auto dir = std::filesystem::temp_directory_path() / ("sph_soak_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string state = (dir / "state.sph").string();

  std::mt19937_64 rng(seed);
  std::size_t current = 0;
  RunConfig cfg = config_of(soak_scenes()[current]);
  Stepper s(cfg, StepperOptions{});
  std::atomic<bool> stop{false};
  SoakChecker checker;
  std::thread reader([&] {
    std::uint64_t last = 0;
    while (!stop.load()) {
      if (const StepperFrame* f = s.latest()) {
        if (f->serial != last) checker.check(*f);
        last = f->serial;
      }
      std::this_thread::sleep_for(200us);
    }
  });

  // Cheap commands often; rebuilds (loads, resets, state loads, comparisons) a few times a second at most,
  // so the command queue never runs far ahead of the engine.
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int ops = 0, rebuilds = 0, loads = 0;
  const auto end = Clock::now() + std::chrono::seconds(seconds);
  auto next_rebuild = Clock::now();
  while (Clock::now() < end) {
    ++ops;
    const unsigned pick = static_cast<unsigned>(rng() % 100);
    if (pick < 12 && Clock::now() >= next_rebuild) {
      next_rebuild = Clock::now() + 250ms;
      ++rebuilds;
      switch (rng() % 6) {
        case 0:
        case 1:
          current = rng() % soak_scenes().size();
          cfg = config_of(soak_scenes()[current]);
          s.load(cfg);
          break;
        case 2: s.reset(random_edit(cfg.params, rng)); break;
        case 3: {
          const SoakScene& sc = soak_scenes()[current];
          if (*sc.value) {
            const double v = sc.lo + (sc.hi - sc.lo) * u(rng);
            s.set_scene_value(sc.value, sc.hi > 1.0 ? std::round(v) : v);
          }
          break;
        }
        case 4:
          s.set_compare(rng() % 2 ? std::vector<std::string>{"visc.alpha=0.25"} : std::vector<std::string>{});
          break;
        default: loads += load_saved(s, state); break;
      }
    } else if (pick < 50) {
      s.post_params(random_edit(cfg.params, rng));
    } else if (pick < 58) {
      s.pause();
    } else if (pick < 70) {
      s.resume();
    } else if (pick < 76) {
      s.step_once();
    } else if (pick < 80) {
      s.save_state(state);
    } else if (pick < 85) {
      s.set_inspect(static_cast<std::int64_t>(rng() % 64) - 4);
    } else if (pick < 90) {
      Push push;  // 2D scenes feel it; elsewhere it acts along the axes they have
      if (rng() % 3) push = Push{{u(rng), u(rng), 0.0}, {u(rng) - 0.5, u(rng) - 0.5, 0.0}, 0.05 + 0.2 * u(rng), 0.05};
      s.set_push(push);
    } else if (pick < 93) {
      s.set_real_time_factor(rng() % 2 ? 0.0 : 0.5);
    } else if (pick < 96) {
      s.set_record_interval(rng() % 2 ? 0.0 : 1e-3);
    } else {
      s.set_tree_probe(static_cast<std::int64_t>(rng() % 8) - 2);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500 + rng() % 2000));
  }
  stop = true;
  reader.join();  // latest() has one reader at a time: from here on, this thread
  EXPECT_EQ(checker.failures(), 0u) << checker.first_failure();
  EXPECT_GE(checker.frames(), 50u);
  std::printf("soak: %ld s, seed %llu: %d commands (%d rebuilds, %d state loads), %llu frames checked, "
              "%llu divergences reported\n", seconds, static_cast<unsigned long long>(seed), ops, rebuilds, loads,
              static_cast<unsigned long long>(checker.frames()), static_cast<unsigned long long>(checker.divergences()));

  // Afterwards: a state saved now loads back to its step and time, and the engine steps on from it.
  s.set_record_interval(0.0);
  s.set_compare({});
  s.set_real_time_factor(0.0);
  s.pause();
  s.load(config_of(soak_scenes()[0]));
  s.step_once();
  s.step_once();
  const StepperFrame* f = wait_for(s, [](const StepperFrame& g) { return g.snapshot.scene == "sod" && g.snapshot.step == 2; }, 120s);
  ASSERT_NE(f, nullptr) << "the engine did not come back to a fresh Sod tube";
  const std::uint64_t world = f->world_serial;
  s.save_state(state);
  ASSERT_NE(wait_for(s, [&](const StepperFrame& g) { return g.notice.find("saved") != std::string::npos; }, 60s), nullptr);
  s.step_once();
  ASSERT_NE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.step == 3; }, 60s), nullptr);
  ASSERT_TRUE(load_saved(s, state));
  f = wait_for(s, [&](const StepperFrame& g) { return g.world_serial > world; }, 60s);
  ASSERT_NE(f, nullptr) << "the saved state was not loaded";
  EXPECT_EQ(f->snapshot.step, 2);
  EXPECT_TRUE(f->error.empty()) << f->error;
  s.resume();
  EXPECT_NE(wait_for(s, [](const StepperFrame& g) { return g.snapshot.step > 6 && !g.diverged; }, 60s), nullptr);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sph
