// Every built-in scene builds and steps without NaN/inf (DivergedError), with its default parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/world.h"

namespace sph {
namespace {

TEST(Registry, NamesAreUniqueAndFindable) {
  const auto& table = scene_registry();
  ASSERT_GE(table.size(), 6u);
  for (const auto& s : table) {
    EXPECT_EQ(find_scene(s.name), &s);
    EXPECT_FALSE(s.description.empty()) << s.name;
  }
  EXPECT_EQ(find_scene("no_such_scene"), nullptr);
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, StepsWithoutNaN) {
  RunConfig cfg = RunConfig::from_scene(GetParam());
  cfg.validate();  // the defaults of every scene are a valid physics it accepts
  World w(cfg);
  for (int i = 0; i < 20; ++i) ASSERT_NO_THROW(w.step()) << GetParam() << " step " << i;
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < p.dim(); ++k) ASSERT_TRUE(std::isfinite(p.x[k][i]) && std::isfinite(p.v[k][i]));
    if (!p.has(Field::Density) && cfg.params.physics.fpm != FpmType::None) {  // FPM points: h is the MLS support
      ASSERT_GT(p[Field::H][i], 0.0);
      continue;
    }
    if (!p.has(Field::Density)) {  // point masses (N-body): h = 0
      ASSERT_EQ(p[Field::H][i], 0.0);
      continue;
    }
    ASSERT_TRUE(std::isfinite(p[Field::Density][i]));
    ASSERT_GT(p[Field::Density][i], 0.0);
    ASSERT_GT(p[Field::H][i], 0.0);
  }
  EXPECT_GT(w.time(), 0.0);
  // a scene with a reference reports one finite-or-nan value per column
  EXPECT_EQ(w.report().reference_values().size(), w.report().reference_columns().size());
}

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const auto& s : scene_registry()) names.push_back(s.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(BuiltIn, EveryScene, ::testing::ValuesIn(scene_names()));

}  // namespace
}  // namespace sph
