// The shipped scene files are the compiled defaults: assets/scenes/NAME.json of every registered scene
// equals what `sph write-assets` generates (as parsed JSON, naming the first key that differs, and as
// text), every registered scene has its file, and every other file there is a variant NAME_VARIANT.json
// of a registered scene NAME that loads and validates. Exact comparison: the files are generated, so no
// tolerance.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "sph/config.h"
#include "sph/scene_asset.h"

namespace sph {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "scenes";

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The first difference between the file's JSON and the compiled one, as "KEY: FILE_VALUE in the file,
/// COMPILED_VALUE compiled" ("" if they are equal).
std::string first_difference(const nlohmann::json& file, const nlohmann::json& compiled) {
  auto value = [](const nlohmann::json& j, const std::string& key) {
    return j.contains(key) ? j.at(key).dump() : std::string("(missing)");
  };
  for (const char* key : {"description", "scene"})
    if (value(file, key) != value(compiled, key))
      return std::string(key) + ": " + value(file, key) + " in the file, " + value(compiled, key) + " compiled";
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json& fp = file.contains("params") ? file.at("params") : none;
  const nlohmann::json& cp = compiled.at("params");
  std::set<std::string> keys;
  for (const auto& [k, _] : fp.items()) keys.insert(k);
  for (const auto& [k, _] : cp.items()) keys.insert(k);
  for (const std::string& k : keys) {
    const bool in_file = fp.contains(k), in_compiled = cp.contains(k);
    if (in_file && in_compiled && fp.at(k) == cp.at(k)) continue;  // 30 == 30.0: numbers compare by value
    return "params." + k + ": " + value(fp, k) + " in the file, " + value(cp, k) + " compiled";
  }
  for (const auto& [k, _] : file.items())
    if (!compiled.contains(k)) return k + ": in the file only";
  return "";
}

TEST(SceneAssets, EveryRegisteredSceneHasItsFileEqualToTheCompiledDefaults) {
  ASSERT_TRUE(std::filesystem::is_directory(kAssets)) << kAssets;
  for (const SceneSpec& s : scene_registry()) {
    const std::filesystem::path path = kAssets / (s.name + ".json");
    const std::string shown = "assets/scenes/" + s.name + ".json";
    if (!std::filesystem::exists(path)) {
      ADD_FAILURE() << shown << " is missing for registered scene " << s.name << "; write it with: " << kWriteAssetsCommand;
      continue;
    }
    const std::string text = read_text(path), generated = scene_asset_json(s.name);
    nlohmann::json file;
    try {
      file = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << shown << " is not JSON (" << e.what() << "); regenerate it with: " << kWriteAssetsCommand;
      continue;
    }
    const std::string diff = first_difference(file, nlohmann::json::parse(generated));
    if (!diff.empty()) {
      ADD_FAILURE() << shown << " differs from the compiled defaults of scene " << s.name << " at " << diff
                    << "; regenerate it with: " << kWriteAssetsCommand;
      continue;
    }
    EXPECT_EQ(text, generated) << shown << ": same values as the compiled defaults but not the generated text; "
                               << "regenerate it with: " << kWriteAssetsCommand;
  }
}

TEST(SceneAssets, EveryOtherFileIsAValidVariantOfARegisteredScene) {
  for (const auto& entry : std::filesystem::directory_iterator(kAssets)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() != ".json") continue;
    const std::string stem = path.stem().string(), shown = "assets/scenes/" + path.filename().string();
    if (find_scene(stem)) continue;  // a scene's own file: the test above
    std::string scene;
    try {
      scene = nlohmann::json::parse(read_text(path)).at("scene").get<std::string>();
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << shown << ": no key 'scene' naming a registered scene (" << e.what() << ")";
      continue;
    }
    if (!find_scene(scene) || !stem.starts_with(scene + "_")) {
      ADD_FAILURE() << shown << " names no registered scene: a scene's file is NAME.json (NAME registered), a "
                    << "variant NAME_VARIANT.json with \"scene\": \"NAME\" (it says \"" << scene << "\")";
      continue;
    }
    try {
      RunConfig::from_file(path.string()).validate();
    } catch (const ConfigError& e) {
      ADD_FAILURE() << shown << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace sph
