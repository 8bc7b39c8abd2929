// Scene families of the built-in table (one function per scene).
#pragma once
#include <vector>

#include "sph/scene.h"

namespace sph::scenes {

SceneSpec sod_scene();
SceneSpec castellanos_scene();
std::vector<SceneSpec> riemann_variant_scenes();  ///< lax, toro1 ... toro5
SceneSpec box_lattice_scene();
SceneSpec box_perturbed_scene();
SceneSpec box_random_scene();
SceneSpec tube2d_scene();
SceneSpec elliptical_drop_scene();
SceneSpec dam_break_scene();
SceneSpec dam_break_slope_scene();
SceneSpec hydrostatic_tank_scene();
SceneSpec two_body_fall_scene();
SceneSpec kepler_scene();
SceneSpec solar_system_scene();
SceneSpec dust_sphere_scene();
SceneSpec dust_collision_scene();
SceneSpec evrard_scene();
SceneSpec polytrope_scene();
SceneSpec colliding_polytropes_scene();
SceneSpec burgers_viscous_scene();
SceneSpec burgers_upwind_scene();
SceneSpec sedov_scene();
SceneSpec sedov3d_scene();
SceneSpec noh_scene();
SceneSpec gresho_scene();
SceneSpec kelvin_helmholtz_scene();

}  // namespace sph::scenes
