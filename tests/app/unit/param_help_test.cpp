// Every tooltip gives a real unit (app/gui/param_help.h): each run parameter and each value of each
// built-in scene (the scene values' tooltips had none, and "unit: -" was all a user saw).
#include <gtest/gtest.h>

#include "param_help.h"
#include "sph/scene.h"

namespace sph::gui {
namespace {

TEST(ParamHelp, EveryRunParameterHasAUnit) {
  for (const ParamInfo& info : param_table()) {
    const std::string line = param_unit_line(info);
    if (!info.choices.empty()) {
      EXPECT_EQ(line.rfind("one of:", 0), 0u) << info.key;
      continue;
    }
    EXPECT_FALSE(info.unit.empty()) << info.key;
    EXPECT_NE(info.unit, "-") << info.key;
    EXPECT_EQ(line.find("unit: -"), std::string::npos) << info.key << ": " << line;
    EXPECT_NE(line.find("unit: " + std::string(info.unit)), std::string::npos) << line;
  }
  EXPECT_EQ(param_unit_line(*find_param("time.cfl")).rfind("unit: dimensionless    range: [0.0001, 2]", 0), 0u);
}

TEST(ParamHelp, EveryValueOfEverySceneHasAUnit) {
  for (const SceneSpec& spec : scene_registry())
    for (const SceneParam& sp : spec.params) {
      EXPECT_FALSE(sp.unit.empty()) << spec.name << " scene." << sp.name;
      EXPECT_NE(sp.unit, "-") << spec.name << " scene." << sp.name;
      EXPECT_NE(scene_value_help(sp).find("\nunit: " + sp.unit + "    range: ["), std::string::npos)
          << scene_value_help(sp);
    }
  const SceneSpec* dam = find_scene("dam_break");
  ASSERT_NE(dam, nullptr);
  EXPECT_NE(scene_value_help(dam->params.front()).find("unit: m    range: [0.01, 100]"), std::string::npos);
}

}  // namespace
}  // namespace sph::gui
