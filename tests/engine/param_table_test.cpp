// The parameter table and RunConfig (sph/param_table.h, sph/config.h, io/config.cpp): a parameter of a
// stage the scene does not run is refused when set explicitly, naming the key and the slot choice that
// leaves it unused; the old flat keys still set the grouped members; unknown keys are refused; the JSON
// dump lists only the parameters of the stages that run; and every stage parameter is used by some
// scene and unused by another (the predicates are neither always true nor always false).
#include "sph/param_table.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "sph/config.h"
#include "sph/scene.h"

namespace sph {
namespace {

/// The message of the ConfigError that fn throws ("" if it throws none).
template <class Fn>
std::string config_error(Fn fn) {
  try {
    fn();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(ParamTable, ParameterOfAStageTheSceneDoesNotRunIsRefused) {
  // box_lattice runs without viscosity (seed 000 eqs. 3.3.29 have none), so visc.alpha has no effect.
  for (const char* key : {"alpha", "visc.alpha"}) {
    RunConfig cfg = RunConfig::from_scene("box_lattice");
    ASSERT_EQ(cfg.params.physics.viscosity, ViscType::None);
    cfg.set(key, "5", "test");  // accepted as a value...
    EXPECT_EQ(cfg.params.visc.alpha, 5.0);
    const std::string msg = config_error([&] { cfg.validate(); });  // ...but refused for this scene
    EXPECT_TRUE(contains(msg, "'visc.alpha'")) << key << ": " << msg;
    EXPECT_TRUE(contains(msg, "physics.viscosity = none")) << key << ": " << msg;
    EXPECT_TRUE(contains(msg, "test")) << "the origin is named: " << msg;
  }
}

TEST(ParamTable, ChoosingTheStageMakesItsParameterValid) {
  RunConfig cfg = RunConfig::from_scene("box_lattice");
  cfg.set("physics.viscosity", "monaghan", "test");
  cfg.set("visc.alpha", "5", "test");
  EXPECT_NO_THROW(cfg.validate());
  EXPECT_EQ(cfg.params.physics.viscosity, ViscType::Monaghan);
  EXPECT_EQ(cfg.params.visc.alpha, 5.0);
}

TEST(ParamTable, OldFlatKeysSetTheGroupedMembers) {
  RunConfig cfg = RunConfig::from_scene("sod");  // runs Monaghan viscosity and variable h
  cfg.set("alpha", "0.5", "test");
  cfg.set("eta", "1.5", "test");
  cfg.set("kernel", "M6", "test");
  cfg.set("cfl", "0.2", "test");
  cfg.set("t_end", "0.1", "test");
  cfg.set("integrator", "rk4", "test");
  cfg.set("h_mode", "fixed", "test");
  EXPECT_NO_THROW(cfg.validate());
  EXPECT_EQ(cfg.params.visc.alpha, 0.5);
  EXPECT_EQ(cfg.params.kernel.eta, 1.5);
  EXPECT_EQ(cfg.params.kernel.type, KernelType::M6);
  EXPECT_EQ(cfg.params.time.cfl, 0.2);
  EXPECT_EQ(cfg.params.time.t_end, 0.1);
  EXPECT_EQ(cfg.params.time.integrator, IntegratorType::RK4);
  EXPECT_EQ(cfg.params.physics.smoothing, HMode::Fixed);
  // recorded under their grouped keys
  for (const char* key : {"visc.alpha", "kernel.eta", "kernel.type", "time.cfl", "time.t_end", "time.integrator",
                          "physics.smoothing"})
    EXPECT_EQ(cfg.explicit_keys.count(key), 1u) << key;
  EXPECT_EQ(cfg.explicit_keys.count("alpha"), 0u);
  // an alias resolves to the same table entry as its key
  EXPECT_EQ(find_param("alpha"), find_param("visc.alpha"));
  EXPECT_EQ(find_param("h_mode"), find_param("physics.smoothing"));
}

TEST(ParamTable, UnknownKeysAndBadValuesAreRefused) {
  RunConfig cfg = RunConfig::from_scene("sod");
  const Params before = cfg.params;
  EXPECT_THROW(cfg.set("no_such_key", "1", "test"), ConfigError);
  EXPECT_THROW(cfg.set("visc.no_such_member", "1", "test"), ConfigError);
  EXPECT_THROW(cfg.set("scene.no_such_value", "1", "test"), ConfigError);
  EXPECT_THROW(cfg.set("visc.alpha", "50", "test"), ConfigError);     // range [0, 10]
  EXPECT_THROW(cfg.set("visc.alpha", "1.0x", "test"), ConfigError);   // trailing junk
  EXPECT_THROW(cfg.set("kernel.type", "M7", "test"), ConfigError);    // not a kernel
  EXPECT_THROW(cfg.set("physics.eos", "van_der_waals", "test"), ConfigError);
  EXPECT_THROW(cfg.set("h.max_iter", "2.5", "test"), ConfigError);    // integer
  EXPECT_TRUE(cfg.params == before) << "a refused value changes nothing";
  EXPECT_TRUE(cfg.explicit_keys.empty());
  EXPECT_EQ(find_param("no_such_key"), nullptr);
}

TEST(ParamTable, JsonListsOnlyTheParametersOfStagesThatRun) {
  const std::string box = RunConfig::from_scene("box_lattice").to_json();
  const std::string sod = RunConfig::from_scene("sod").to_json();
  EXPECT_FALSE(contains(box, "\"visc.")) << box;
  EXPECT_TRUE(contains(sod, "\"visc.alpha\"")) << sod;
  EXPECT_TRUE(contains(box, "\"physics.viscosity\": \"none\"")) << "the slot itself is always listed";
  EXPECT_TRUE(contains(box, "\"time.cfl\"")) << "parameters of every scene are always listed";
}

/// Some physics the scene accepts (its defaults with `slot` set to one of its allowed options, and at most
/// one other slot changed too, e.g. the energy equation off for an isothermal gas) that validates and
/// makes `info` active.
bool reachable(const SceneSpec& s, const ParamInfo& info) {
  if (info.is_active(s.defaults)) return true;
  auto ok = [&](const Params& p) { return p.physics.validate().empty() && info.is_active(p); };
  // or by a choice of the stage's own (visc.switch = cullen_dehnen for the switch's parameters)
  for (const ParamInfo& c : param_table()) {
    if (c.choices.empty() || c.slot != info.slot || &c == &info) continue;
    for (const std::string& choice : c.choices) {
      Params q = s.defaults;
      std::string err;
      if (c.is_active(q) && c.set(q, choice, err) && ok(q)) return true;
    }
  }
  for (const std::string& option : slot_info(info.slot).options) {
    Params p = s.defaults;
    if (!s.allows(info.slot, option) || !p.physics.set(info.slot, option)) continue;
    if (ok(p)) return true;
    for (const SlotInfo& other : slot_table()) {
      if (other.slot == info.slot) continue;
      for (const std::string& o2 : other.options) {
        Params q = p;
        if (s.allows(other.slot, o2) && q.physics.set(other.slot, o2) && ok(q)) return true;
      }
    }
  }
  return false;
}

TEST(ParamTable, EveryStageParameterIsUsedBySomeSceneAndUnusedByAnother) {
  // "Used" by a scene: active for its defaults, or reachable from them by choosing the stage in the
  // parameter's slot (see reachable()): the GUI can then show it. Every predicate must also be false for
  // some scene's defaults, or it would not need to exist.
  int predicates = 0;
  for (const ParamInfo& info : param_table()) {
    if (!info.active) continue;
    ++predicates;
    ASSERT_NE(info.slot, Slot::Count) << info.key << ": a stage parameter names the slot of its stage";
    EXPECT_FALSE(info.stage.empty()) << info.key << ": and the stage, for messages";
    bool active_default = false, inactive_default = false, can_run = false;
    for (const SceneSpec& s : scene_registry()) {
      (info.is_active(s.defaults) ? active_default : inactive_default) = true;
      can_run = can_run || reachable(s, info);
    }
    std::printf("%-22s active in some scene's defaults: %s\n", std::string(info.key).c_str(),
                active_default ? "yes" : (can_run ? "no, reachable by choosing its stage" : "no, unreachable"));
    EXPECT_TRUE(inactive_default) << info.key << ": used by every scene, yet it has an activity predicate";
    EXPECT_TRUE(can_run) << info.key << ": no scene can run the stage that uses it";
  }
  EXPECT_GT(predicates, 10);
}

}  // namespace
}  // namespace sph
