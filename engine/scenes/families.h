// Scene families of the built-in table (one function per scene).
#pragma once
#include "sph/scene.h"

namespace sph::scenes {

SceneSpec sod_scene();
SceneSpec castellanos_scene();
SceneSpec box_lattice_scene();
SceneSpec box_perturbed_scene();
SceneSpec box_random_scene();
SceneSpec tube2d_scene();
SceneSpec elliptical_drop_scene();
SceneSpec dam_break_scene();
SceneSpec dam_break_slope_scene();
SceneSpec hydrostatic_tank_scene();

}  // namespace sph::scenes
