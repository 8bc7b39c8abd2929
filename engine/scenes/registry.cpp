// The built-in scenes: the table generated from the SPH_SCENE markers of engine/scenes/*.cpp
// (scene_registration.h; static self-registration breaks inside static libraries), and lookup by name.
#include "scene_registration.h"

namespace sph {

const std::vector<SceneSpec>& scene_registry() {
  static const std::vector<SceneSpec> table = scenes::builtin_scenes();
  return table;
}

const SceneSpec* find_scene(std::string_view name) {
  for (const auto& s : scene_registry())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace sph
