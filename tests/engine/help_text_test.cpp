// The text of `sph help SCENE` and `sph params` (sph/help_text.h): every parameter of the scene's stages
// with its unit and range, the scene's own values, its reference columns; every key in `sph params`.
#include "sph/help_text.h"

#include <gtest/gtest.h>

#include "sph/param_table.h"

namespace sph {
namespace {

TEST(SceneHelp, SodListsItsStagesParametersValuesAndReference) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "800", "test");
  const std::string text = scene_help(cfg);
  EXPECT_NE(text.find("sod (1D"), std::string::npos);
  EXPECT_NE(text.find("physics.density"), std::string::npos);
  EXPECT_NE(text.find("each step runs: density: summation"), std::string::npos);
  for (const ParamInfo& info : param_table()) {
    if (info.is_slot()) continue;
    const bool listed = text.find("  " + std::string(info.key) + " ") != std::string::npos;
    EXPECT_EQ(listed, info.is_active(cfg.params)) << info.key;  // exactly the keys of the stages it runs
  }
  EXPECT_NE(text.find("adiabatic index"), std::string::npos);       // a description with its seed equation
  EXPECT_NE(text.find("seed 000 eq. 3.3.23"), std::string::npos);
  EXPECT_NE(text.find("dimensionless, range [1.0001, 10], default 1.4"), std::string::npos);  // gas.gamma
  EXPECT_NE(text.find("scene.n_left"), std::string::npos);
  EXPECT_NE(text.find("= 800"), std::string::npos);
  EXPECT_NE(text.find("= 800           count, range [4, 1e+06], integer, default 400"), std::string::npos);
  EXPECT_NE(text.find("error norms"), std::string::npos);
  EXPECT_NE(text.find("L1_rho"), std::string::npos);
}

TEST(SceneHelp, ASceneWithoutReferenceSaysSo) {
  const std::string text = scene_help(RunConfig::from_scene("box_lattice"));
  EXPECT_NE(text.find("Reference: none"), std::string::npos);
  EXPECT_EQ(text.find("visc.alpha"), std::string::npos);  // no viscosity stage, no viscosity key
}

TEST(ParamsHelp, ListsEveryKeyWithItsStage) {
  const std::string text = params_help();
  for (const ParamInfo& info : param_table()) EXPECT_NE(text.find("  " + std::string(info.key) + " "), std::string::npos) << info.key;
  EXPECT_NE(text.find("used by the Monaghan viscosity stage"), std::string::npos);
}

TEST(ScenesHelp, OneLinePerScene) {
  const std::string text = scenes_help();
  for (const SceneSpec& s : scene_registry()) EXPECT_NE(text.find("  " + s.name + " "), std::string::npos) << s.name;
}

}  // namespace
}  // namespace sph
