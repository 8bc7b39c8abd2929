// The explicit table of built-in scenes (static self-registration breaks inside static libraries).
#include "families.h"

namespace sph {

const std::vector<SceneSpec>& scene_registry() {
  static const std::vector<SceneSpec> table = [] {
    std::vector<SceneSpec> t = {scenes::sod_scene(), scenes::castellanos_scene()};
    for (SceneSpec& s : scenes::riemann_variant_scenes()) t.push_back(std::move(s));
    for (SceneSpec& s : std::vector<SceneSpec>{scenes::box_lattice_scene(),
      scenes::box_perturbed_scene(), scenes::box_random_scene(), scenes::tube2d_scene(),
      scenes::elliptical_drop_scene(), scenes::dam_break_scene(), scenes::dam_break_slope_scene(),
      scenes::hydrostatic_tank_scene(), scenes::two_body_fall_scene(), scenes::kepler_scene(),
      scenes::solar_system_scene(), scenes::dust_sphere_scene(), scenes::dust_collision_scene(),
      scenes::evrard_scene(), scenes::polytrope_scene(), scenes::colliding_polytropes_scene(),
      scenes::burgers_viscous_scene(), scenes::burgers_upwind_scene(), scenes::sedov_scene(),
      scenes::sedov3d_scene(), scenes::noh_scene(), scenes::gresho_scene(), scenes::kelvin_helmholtz_scene()})
      t.push_back(std::move(s));
    return t;
  }();
  return table;
}

const SceneSpec* find_scene(std::string_view name) {
  for (const auto& s : scene_registry())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace sph
