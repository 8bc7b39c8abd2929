// The checks that keep a run from going bad silently (engine/src/world/world_checks.cpp): on Sod, a
// degraded run (forward Euler, cfl = 0.7) is warned about by name and a run at cfl = 0.9 stops before
// its energy is garbage; a clean run has no warnings; an h solve that stops converging mid-run and a
// run past the time its reference applies to are warned about, naming the particle or the time; a state
// beyond single precision (what snapshots and outputs hold), or a NaN sound speed, stops the run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sph/world.h"

namespace sph {
namespace {

World& run_to_end(World& w) {
  w.advance_to(w.params().time.t_end);
  return w;
}

const RunWarning* find(const World& w, const std::string& kind) {
  for (const RunWarning& x : w.checks().warnings())
    if (x.kind == kind) return &x;
  return nullptr;
}

/// Up to 200 steps of cfg; every snapshot before the run stops must hold finite floats. `why` gets the
/// DivergedError's message (empty if the run never stopped).
void run_until_stopped(const RunConfig& cfg, std::string& why) {
  World w(cfg);
  try {
    for (int s = 0; s < 200; ++s) {
      w.step();
      const Snapshot snap = w.report().snapshot();
      for (const auto& f : snap.fields)
        for (float v : f.values) ASSERT_TRUE(std::isfinite(v)) << f.name << " at step " << w.steps() << " is " << v;
    }
  } catch (const DivergedError& e) {
    why = e.what();
  }
}

TEST(WorldChecks, CleanSodRunHasNoWarnings) {
  // leapfrog at cfl 0.3 keeps E_tot to 7e-6 of its scale (bound 1e-3); the walls stay out of reach
  World w(RunConfig::from_scene("sod"));
  run_to_end(w);
  EXPECT_TRUE(w.checks().warnings().empty()) << w.checks().warnings().front().message;
}

TEST(WorldChecks, ForwardEulerOnSodIsWarnedAbout) {
  // forward Euler gains 4.6e-3 of the energy scale by t = 0.2: beyond the bound, named in the message
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("time.integrator", "euler", "test");
  World w(cfg);
  run_to_end(w);
  const RunWarning* e = find(w, "energy");
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("forward Euler is unstable"), std::string::npos) << e->message;
  EXPECT_GT(e->step, 0);
}

TEST(WorldChecks, LongStepsOnSodAreWarnedAboutThenStopped) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("time.cfl", "0.7", "test");  // degraded: E_tot +1.2%, L1(rho) 2.7x worse
  World w(cfg);
  run_to_end(w);
  const RunWarning* e = find(w, "energy");
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("time.cfl"), std::string::npos) << e->message;

  cfg.set("time.cfl", "0.9", "test");  // unstable: E_tot reached 4e11 before a NaN without the check
  World bad(cfg);
  std::int64_t particle = -1, step = -1;
  std::string why;
  try {
    run_to_end(bad);
  } catch (const DivergedError& err) {
    particle = err.particle;
    step = err.step;
    why = err.what();
  }
  ASSERT_FALSE(why.empty()) << "cfl = 0.9 ran to the end";
  EXPECT_NE(why.find("total energy grew"), std::string::npos) << why;
  EXPECT_GE(particle, 0) << why;  // named: the particle with the largest acceleration
  EXPECT_LT(step, 30) << why;     // at most 10% of the scale gained: stopped within a few steps
  // what it had written up to then is bounded: the last energy is within the stop threshold's jump
  const Diagnostics d = bad.report().diagnostics();
  EXPECT_TRUE(std::isfinite(d.E_tot));
}

TEST(WorldChecks, AnHSolveThatStopsConvergingIsWarnedAbout) {
  World w(RunConfig::from_scene("sod"));
  Params p = w.params();
  p.h.max_iter = 1;  // one Newton step cannot follow the shock's compression
  w.set_params(p);
  std::int64_t diverged_at = 1 << 30;
  try {  // it goes on with approximate densities, and later blows up (near step 96)
    for (int s = 0; s < 200; ++s) w.step();
  } catch (const DivergedError& e) {
    diverged_at = e.step;
  }
  const RunWarning* h = find(w, "h_solve");
  ASSERT_NE(h, nullptr);
  EXPECT_LT(h->step, diverged_at);  // the warning came first
  EXPECT_GE(h->particle, 0);
  EXPECT_NE(h->message.find("h.max_iter"), std::string::npos) << h->message;
}

TEST(WorldChecks, ARunPastItsReferenceIsWarnedAbout) {
  // Toro 1 on his [0, 1]: the left state moves away from the wall at 0.75, so the wall launches a
  // rarefaction at v + c; it meets the left fan's head (v - c) at t = 0.3 / (2 c), c = sqrt(1.4)
  RunConfig cfg = RunConfig::from_scene("toro1");
  cfg.set("scene.x_lo", "0", "test");
  cfg.set("scene.n_left", "300", "test");
  World w(cfg);
  const double expected = 0.3 / (2.0 * std::sqrt(1.4));
  ASSERT_NEAR(w.report().reference()->valid_until(), expected, 1e-9);
  w.advance_to(0.1);
  EXPECT_EQ(find(w, "reference"), nullptr);
  w.advance_to(0.2);
  const RunWarning* r = find(w, "reference");
  ASSERT_NE(r, nullptr);
  EXPECT_GT(r->t, expected);
  // at the default [-0.3, 1] the reference applies to the end
  World wide(RunConfig::from_scene("toro1"));
  EXPECT_GT(wide.report().reference()->valid_until(), wide.params().time.t_end);
}

// Found by the stepper's soak test: a dam break at a fixed step of 10 s (forward Euler) reached Tait
// pressures above 3.4e38 Pa while every double stayed finite, and its frames showed p = inf without a
// divergence. Every state a step completes now fits the floats of snapshots and outputs, or the run stops.
TEST(WorldChecks, AStateBeyondSinglePrecisionStopsTheRun) {
  RunConfig cfg = RunConfig::from_scene("dam_break");
  cfg.set("scene.dx", "0.1", "test");
  cfg.set("time.integrator", "euler", "test");
  cfg.set("time.dt", "10", "test");
  std::string why;
  run_until_stopped(cfg, why);
  if (HasFatalFailure()) return;
  ASSERT_FALSE(why.empty()) << "200 steps of 10 s did not stop";
  std::printf("%s\n", why.c_str());
}

// An ideal gas whose explicit steps overshoot its cooling: a negative u leaves P finite and the sound
// speed c = sqrt(gamma P/rho) NaN. The run must stop with a reason, and no snapshot before that may
// hold a non-finite value (the display and the outputs would show it).
TEST(WorldChecks, ANegativeInternalEnergyStopsTheRun) {
  // of Sod, Lax, Toro 1-3, Sedov and Noh at fixed dt of 5e-4 to 5e-3, the run that first went bad in its
  // sound speed (the others stop on velocity or the energy guard first)
  RunConfig cfg = RunConfig::from_scene("toro1");
  cfg.set("time.dt", "0.005", "test");
  std::string why;
  run_until_stopped(cfg, why);
  if (HasFatalFailure()) return;
  ASSERT_FALSE(why.empty()) << "200 steps of 0.005 did not stop";
  EXPECT_NE(why.find("non-finite cs"), std::string::npos) << why;
  std::printf("%s\n", why.c_str());
}

}  // namespace
}  // namespace sph
