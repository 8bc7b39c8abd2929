// Individual time steps in the World (time.levels > 1, world_block.cpp):
// - the 2D Sedov blast at n_side = 80 reaches the shock radius and energy of the global step (R_err
//   within 1.2x + 0.002 of it, |dE/E| <= 1e-3 at t = 0.1) with at least 3x fewer particle updates
//   (measured: 3.7x; 6.2x at the default 160);
// - the same steps on one and two threads, and a checkpoint taken inside a block resumes bit for bit;
// - the field `level` shows each particle's step level, the blast's centre on the shortest steps;
// - parameters it cannot step are refused, naming time.levels and the key in the way.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/world.h"
#include "world_steps_util.h"

namespace sph {
namespace {

RunConfig sedov(const std::string& n_side, int levels) {
  RunConfig cfg = RunConfig::from_scene("sedov");
  cfg.set("scene.n_side", n_side, "test");
  cfg.set("time.levels", std::to_string(levels), "test");
  cfg.validate();
  return cfg;
}

struct Blast {
  double R_err, dE;
  std::int64_t updates;
};

Blast run_to_end(const RunConfig& cfg) {
  World w(cfg);
  w.advance_to(0.1);
  return {w.report().reference_value("R_err"), w.report().reference_value("dE_rel"),
          w.report().diagnostics().updates};
}

TEST(WorldBlock, SedovReachesTheGlobalStepsResultWithFewerUpdates) {
  const Blast global = run_to_end(sedov("80", 1)), block = run_to_end(sedov("80", 6));
  std::printf("sedov n_side 80: global R_err %.4f |dE/E| %.2e %lld updates; levels 6: R_err %.4f |dE/E| %.2e %lld "
              "updates\n", global.R_err, global.dE, static_cast<long long>(global.updates), block.R_err, block.dE,
              static_cast<long long>(block.updates));
  EXPECT_LE(block.R_err, 1.2 * global.R_err + 0.002);
  EXPECT_LE(block.dE, 1e-3);
  EXPECT_GE(static_cast<double>(global.updates), 3.0 * static_cast<double>(block.updates));
}

TEST(WorldBlock, SameStepsOnAnyThreadCount) { test::expect_same_steps_on_one_and_two_threads(sedov("40", 5), 70); }

TEST(WorldBlock, CheckpointInsideABlockResumesBitwise) {
  test::expect_resume_bitwise(sedov("40", 5), 45, 90);  // past a reordering (every 16 steps), inside a block
}

TEST(WorldBlock, LevelFieldShowsTheHotCentreOnTheShortestSteps) {
  World w(sedov("40", 5));
  for (int k = 0; k < 5; ++k) w.step();
  const Particles& p = w.particles();
  const auto& level = p[Field::StepLevel];
  const auto& u = p[Field::Energy];
  std::size_t hot = 0, cold = 0;
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    EXPECT_EQ(level[i], std::floor(level[i]));
    EXPECT_GE(level[i], 0.0);
    EXPECT_LE(level[i], 4.0);
    if (u[i] > u[hot]) hot = i;
    if (u[i] < u[cold]) cold = i;
  }
  EXPECT_GE(level[hot], level[cold] + 2.0) << "the blast steps shorter than the cold gas";
}

TEST(WorldBlock, RefusesWhatItCannotStep) {
  auto refusal = [](std::vector<std::pair<std::string, std::string>> sets) {
    RunConfig cfg = RunConfig::from_scene("sod");
    cfg.set("time.levels", "4", "test");
    for (const auto& [k, v] : sets) cfg.set(k, v, "test");
    try {
      World w(cfg);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal({}), "");
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"time.integrator", "rk4"}, {"time.dt", "0.001"}, {"visc.switch", "cullen_dehnen"}, {"physics.xsph", "on"}}) {
    const std::string why = refusal({{key, value}});
    EXPECT_NE(why.find("time.levels = 4"), std::string::npos) << why;
    EXPECT_NE(why.find(key), std::string::npos) << why;
  }
}

}  // namespace
}  // namespace sph
