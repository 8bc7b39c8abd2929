// The scene's one-line description as it applies to the values it runs with: the description is
// written for the defaults ("500 random particles"), so a number in it that is a changed value's
// default (and no other value's) is replaced by the value, and the other changed values are listed.
#pragma once
#include <string>

#include "sph/scene.h"

namespace sph::gui {

/// spec.description for `values` (spec.description itself when they are the defaults).
std::string describe_scene(const SceneSpec& spec, const SceneValues& values);

/// The hint of the scene-file field: the running scene's own file (it said assets/scenes/sod.json for
/// every scene).
std::string scene_file_hint(const std::string& scene);

}  // namespace sph::gui
