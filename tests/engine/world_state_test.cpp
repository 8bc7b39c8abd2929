// World::save_state / restore_state: a world stepped N times, saved, restored into a new world of the
// same configuration and stepped N more is bitwise the world stepped 2N times (its whole saved state
// compared byte for byte), for every integrator and a scene of each kind; a state refuses a world of
// another scene.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "sph/checkpoint.h"
#include "sph/config.h"
#include "sph/world.h"

namespace sph {
namespace {

struct Case {
  std::string scene;
  std::vector<std::pair<std::string, std::string>> sets;
  int steps;  ///< steps before and after the save (past a reordering at 16, list rebuilds)
  std::string tag = "";  ///< added to the scene in the test's name
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene; }

RunConfig config(const Case& c, const std::string& integrator) {
  RunConfig cfg = RunConfig::from_scene(c.scene);
  for (const auto& [k, v] : c.sets) cfg.set(k, v, "test");
  cfg.set("time.integrator", integrator, "test");
  cfg.validate();
  return cfg;
}

class WorldState : public ::testing::TestWithParam<std::tuple<Case, std::string>> {};

TEST_P(WorldState, RestoredRunIsBitwiseTheUninterruptedOne) {
  const auto& [c, integrator] = GetParam();
  const RunConfig cfg = config(c, integrator);
  World whole(cfg), first(cfg);
  for (int k = 0; k < 2 * c.steps; ++k) whole.step();
  for (int k = 0; k < c.steps; ++k) first.step();
  const std::string saved = first.save_state();
  World resumed(cfg);
  resumed.restore_state(saved, "test");
  EXPECT_EQ(resumed.save_state(), saved);  // the restore takes everything back
  for (int k = 0; k < c.steps; ++k) resumed.step();
  EXPECT_EQ(resumed.steps(), whole.steps());
  EXPECT_EQ(resumed.time(), whole.time());
  EXPECT_TRUE(resumed.save_state() == whole.save_state()) << "the states differ after the restore";
  for (int k = 0; k < 3; ++k) EXPECT_EQ(resumed.particles().x[k], whole.particles().x[k]);
}

const Case kCases[] = {
    {"sod", {{"scene.n_left", "60"}}, 20},
    {"dam_break", {{"scene.dx", "0.1"}}, 20},
    {"evrard", {{"scene.n", "200"}}, 10},
    {"kepler", {{"time.dt", "0.0005"}}, 20},  // forward Euler at 0.002 leaves the energy bound by step 30
    {"burgers_upwind", {{"scene.n", "100"}}, 20},
    // alpha per particle and the switch's started flag (a stage's saved state)
    {"sod", {{"scene.n_left", "60"}, {"visc.switch", "cullen_dehnen"}}, 20, "_switch"},
};

INSTANTIATE_TEST_SUITE_P(ScenesAndIntegrators, WorldState,
                         ::testing::Combine(::testing::ValuesIn(kCases),
                                            ::testing::Values("euler", "leapfrog", "predictor_corrector", "rk4")),
                         [](const auto& info) {
                           return std::get<0>(info.param).scene + std::get<0>(info.param).tag + "_" +
                                  std::get<1>(info.param);
                         });

TEST(WorldStateRefusal, AStateOfAnotherSceneIsRefused) {
  World sod(RunConfig::from_scene("sod"));
  RunConfig dam = RunConfig::from_scene("dam_break");
  dam.set("scene.dx", "0.1", "test");
  World other(dam);
  EXPECT_THROW(other.restore_state(sod.save_state(), "test"), CheckpointError);
  const std::string s = sod.save_state();
  World sod2(RunConfig::from_scene("sod"));
  EXPECT_THROW(sod2.restore_state(s.substr(0, s.size() / 2), "test"), CheckpointError);  // cut short
}

}  // namespace
}  // namespace sph

namespace sph {
namespace {

// A checkpoint's scene text (RunConfig::to_json) builds the same configuration again: what the GUI's
// "load state" relies on for a checkpoint of `sph run`.
TEST(WorldStateConfig, SceneTextBuildsTheSameConfiguration) {
  for (const Case& c : kCases) {
    const RunConfig cfg = config(c, "rk4");
    RunConfig again = RunConfig::from_json_text(cfg.to_json(), "test");
    again.validate();
    EXPECT_EQ(again.to_json(), cfg.to_json()) << c.scene;
  }
}

}  // namespace
}  // namespace sph

namespace sph {
namespace {

// The Kelvin-Helmholtz reference fits a growth rate over every evaluation so far: that history comes
// back with the state, so the resumed run's rate and point count are the uninterrupted run's.
TEST(WorldStateReference, AFitOverPastEvaluationsGoesOn) {
  RunConfig cfg = RunConfig::from_scene("kelvin_helmholtz");
  cfg.set("scene.n_side", "16", "test");
  cfg.set("scene.fit_t0", "0", "test");  // every evaluation is in the fit window
  cfg.validate();
  World whole(cfg), first(cfg);
  for (int k = 0; k < 12; ++k) { whole.step(); whole.report().reference_values(); }
  for (int k = 0; k < 6; ++k) { first.step(); first.report().reference_values(); }
  World resumed(cfg);
  resumed.restore_state(first.save_state(), "test");
  for (int k = 0; k < 6; ++k) { resumed.step(); resumed.report().reference_values(); }
  EXPECT_EQ(resumed.report().reference_value("fit_points"), whole.report().reference_value("fit_points"));
  EXPECT_EQ(resumed.report().reference_value("rate_fit"), whole.report().reference_value("rate_fit"));
  EXPECT_GE(whole.report().reference_value("fit_points"), 12.0);
}

}  // namespace
}  // namespace sph
