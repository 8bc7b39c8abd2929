// The shipped scene file of a built-in scene, assets/scenes/NAME.json, is generated from the compiled
// defaults (`sph scene-json NAME`, `sph write-assets assets/scenes`) and checked equal to them by
// tests/scenes/scene_assets_test.cpp: a changed default fails that test until the file is regenerated.
#pragma once
#include <string>

namespace sph {

/// The command (from the source tree, after a build) that regenerates every assets/scenes/NAME.json.
inline constexpr const char* kWriteAssetsCommand = "build/app/headless/sph write-assets assets/scenes";

/// The text of assets/scenes/NAME.json for the built-in scene `name`: {"description": the scene's own
/// line, "scene": NAME, "params": every parameter of its stages and every scene.* key at the defaults
/// (as RunConfig::to_json)}, indented by two spaces, ending in a newline. Throws ConfigError for a
/// name that is no built-in scene.
std::string scene_asset_json(const std::string& name);

}  // namespace sph
