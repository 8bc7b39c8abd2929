// `sph scene-json NAME` and `sph write-assets DIR`: the shipped scene files assets/scenes/NAME.json,
// generated from the compiled defaults (sph/scene_asset.h).
#pragma once
#include <string>

namespace sph::cli {

/// Prints the scene file of built-in scene `name` on stdout; exit 3 (kInvalidScene) for an unknown name.
int scene_json_command(const std::string& name);

/// Writes DIR/NAME.json for every built-in scene (DIR must exist); exit 4 (kIoError) if a file cannot
/// be written. Files of DIR that are not a scene's (hand-written variants) are left alone.
int write_assets_command(const std::string& dir);

}  // namespace sph::cli
