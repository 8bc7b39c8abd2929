// The scene description follows the scene values (app/gui/scene_text.h): it said "500 random
// particles" with scene.count = 20000.
#include <gtest/gtest.h>

#include <filesystem>

#include "scene_text.h"

namespace sph::gui {
namespace {

SceneValues defaults(const SceneSpec& s) {
  SceneValues v;
  for (const SceneParam& p : s.params) v[p.name] = p.value;
  return v;
}

TEST(SceneText, DefaultsGiveTheDescriptionAsWritten) {
  for (const SceneSpec& s : scene_registry()) EXPECT_EQ(describe_scene(s, defaults(s)), s.description) << s.name;
}

TEST(SceneText, AChangedCountReplacesItsNumber) {
  const SceneSpec* box = find_scene("box_random");
  ASSERT_NE(box, nullptr);
  ASSERT_NE(box->description.find("500 random particles"), std::string::npos);  // written for the default
  SceneValues v = defaults(*box);
  v["count"] = 20000;
  const std::string d = describe_scene(*box, v);
  EXPECT_NE(d.find("20000 random particles"), std::string::npos) << d;
  EXPECT_EQ(d.find("500"), std::string::npos) << d;
  EXPECT_NE(d.find("seed 000 §4.1.4"), std::string::npos) << d;  // "000" and "4.1.4" are not the count
}

TEST(SceneText, ValuesNotInTheTextAreListed) {
  const SceneSpec* sod = find_scene("sod");
  ASSERT_NE(sod, nullptr);
  SceneValues v = defaults(*sod);
  v["n_left"] = 800;
  v["rho_r"] = 0.25;
  const std::string d = describe_scene(*sod, v);
  EXPECT_NE(d.find("n_left = 800"), std::string::npos) << d;
  // 0.125 is in the text as rho_r's default: replaced, not listed
  EXPECT_NE(d.find("1,1 | 0.25,0.1"), std::string::npos) << d;
  EXPECT_EQ(d.find("rho_r ="), std::string::npos) << d;
}

TEST(SceneText, FileHintIsTheRunningScenesOwnFile) {
  for (const SceneSpec& s : scene_registry()) {
    const std::string hint = scene_file_hint(s.name);
    EXPECT_EQ(hint, "assets/scenes/" + s.name + ".json");
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(SPH_SOURCE_DIR) / hint)) << hint;
  }
}

}  // namespace
}  // namespace sph::gui
