// How a scene file registers its scenes, with no table to edit: the scene function is defined with a
// marker at the start of a line, inside namespace sph::scenes,
//   SPH_SCENE(ORDER, function) { ... return spec; }        // one scene: SceneSpec function()
//   SPH_SCENES(ORDER, function) { ... return specs; }      // a family: std::vector<SceneSpec> function()
// engine/scenes/scene_table.cmake reads the markers of engine/scenes/*.cpp at build time and generates
// builtin_scenes() (build/engine/generated/scene_table.cpp). ORDER (a whole number, unique) is the
// position in `sph list` and the GUI, ascending; the built-in scenes are numbered in tens so a new one
// fits between two.
#pragma once
#include <utility>
#include <vector>

#include "sph/scene.h"

#define SPH_SCENE(order, function) ::sph::SceneSpec function()
#define SPH_SCENES(order, function) std::vector<::sph::SceneSpec> function()

namespace sph::scenes {

/// Every marked scene in ORDER (the generated table).
std::vector<SceneSpec> builtin_scenes();

/// Appends one scene or a family to the table.
inline void add_scenes(std::vector<SceneSpec>& table, SceneSpec s) { table.push_back(std::move(s)); }
inline void add_scenes(std::vector<SceneSpec>& table, std::vector<SceneSpec> family) {
  for (SceneSpec& s : family) table.push_back(std::move(s));
}

}  // namespace sph::scenes
