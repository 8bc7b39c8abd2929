// "Model only what a scene needs": for every built-in scene, every slot it may drop (the option "none"
// is valid there and the scene accepts it) runs: the World builds, steps, and allocates no field of the
// dropped stage. Also: a scene with no viscosity refuses its parameters (e.g. visc.alpha on box_lattice).
#include <gtest/gtest.h>

#include <algorithm>

#include "core/pipeline.h"
#include "sph/param_table.h"
#include "sph/world.h"

namespace sph {
namespace {

TEST(SlotNone, EverySlotAStageMayDropRuns) {
  int ran = 0;
  for (const SceneSpec& scene : scene_registry()) {
    for (const SlotInfo& slot : slot_table()) {
      if (std::find(slot.options.begin(), slot.options.end(), "none") == slot.options.end()) continue;
      RunConfig cfg = RunConfig::from_scene(scene.name);
      if (cfg.params.physics.get(slot.slot) == "none") continue;
      if (!cfg.params.physics.set(slot.slot, "none")) continue;
      // a slot others depend on (no density under a force) is refused, not crashed on
      if (!cfg.params.physics.validate().empty() || !scene.allows(slot.slot, "none")) {
        EXPECT_THROW(World{cfg}, ConfigError) << scene.name << " physics." << slot.key << " = none";
        continue;
      }
      if (cfg.values.count("dx")) cfg.set("scene.dx", "0.1", "test");  // small liquid scenes
      World w(cfg);
      for (int s = 0; s < 3; ++s) ASSERT_NO_THROW(w.step()) << scene.name << " physics." << slot.key << " = none";
      // only the remaining stages' fields are allocated
      EXPECT_EQ(w.particles().fields(), Pipeline(cfg.params, scene.dim).fields()) << scene.name;
      ++ran;
    }
  }
  EXPECT_GE(ran, 16);  // measured: 16 (slot, scene) pairs of the 10 built-in scenes run with "none"
}

TEST(SlotNone, ParametersOfAMissingStageAreRefused) {
  RunConfig cfg = RunConfig::from_scene("box_lattice");
  cfg.set("alpha", "5", "--set alpha=5");
  try {
    cfg.validate();
    FAIL() << "visc.alpha accepted although box_lattice has no viscosity stage";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("visc.alpha"), std::string::npos) << m;
    EXPECT_NE(m.find("physics.viscosity = none"), std::string::npos) << m;
    EXPECT_NE(m.find("--set alpha=5"), std::string::npos) << m;
  }
  // scene.json lists only the parameters of the stages the scene runs
  EXPECT_EQ(RunConfig::from_scene("box_lattice").to_json().find("visc."), std::string::npos);
  EXPECT_NE(RunConfig::from_scene("sod").to_json().find("visc.alpha"), std::string::npos);
}

}  // namespace
}  // namespace sph
