// Water at rest in a tank under gravity: it should stay at rest with P = rho0 g (H - y). Starts from the
// hydrostatic density (Tait EOS inverted); the settling of the small start-up waves is damped by the
// artificial viscosity. Dummy (default) or Lennard-Jones walls.
#include <cmath>

#include "liquid_tank.h"
#include "scene_registration.h"
#include "scene_util.h"

namespace sph::scenes {

SPH_SCENE(110, hydrostatic_tank_scene) {
  SceneSpec s = liquid_scene(
      "hydrostatic_tank",
      "water at rest in a 1 m tank under gravity; pressure against rho0 g (H - y)", {"dummy", "lennard_jones"});
  hydrostatic_tank_head(s, 1.0, 0.025, 1.0, "tank width [m]", 1);
  s.build = [](const Params& prm, const SceneValues& v) {
    const double W = v.at("width"), H = v.at("depth"), dx = v.at("dx");
    SceneSetup out = tank_setup(prm, W, H, W, 1.2 * H, dx);
    out.domain.lo = {-0.1 * W, -0.1 * H, 0.0};
    out.domain.hi = {1.1 * W, 1.2 * H, 1.0};
    return out;
  };
  s.error_bounds = {{"L1_p_rel", 0.013}};  // measured to t = 1: 8.5e-3 (the start-up oscillation at t = 0.2)
  s.assumptions = {resolution("scene.dx", 1e-4, 0.025), weakly_compressible("depth", 1.0)};
  return s;
}

}  // namespace sph::scenes
