// Water at rest in a square 3D tank under gravity along -z (the 3D views' up): it should stay at rest
// with P = rho0 g (H - z). The 2D tank's physics in three dimensions: hydrostatic start (Tait EOS inverted),
// dummy walls (Adami et al. 2012) in `layers` lattice rows under the floor and outside the four sides,
// standard-corrected forces (seed 001 eqs. 53-55) with delta-SPH density diffusion.
#include <cmath>

#include "liquid_tank.h"
#include "scene_registration.h"
#include "scene_util.h"

namespace sph::scenes {
namespace {

/// Fluid of depth H filling [0, W]^2 in x and y, then the dummy walls around it up to `top`, on a cubic
/// lattice of spacing dx (fluid centres dx/2 inside the faces).
Particles tank_3d(const Params& prm, double W, double H, double top, double dx) {
  const double T = dummy_layers(prm, 3) * dx;
  LiquidLayout lay;
  const auto count = [&](double len) { return static_cast<long>(std::floor(len / dx + 1e-9)); };
  for (long k = 0; k < count(H); ++k)
    for (long j = 0; j < count(W); ++j)
      for (long i = 0; i < count(W); ++i) lay.fluid.push_back({(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx});
  for (long k = 0; k < count(top + T); ++k)
    for (long j = 0; j < count(W + 2 * T); ++j)
      for (long i = 0; i < count(W + 2 * T); ++i) {
        const Vec3 x{-T + (i + 0.5) * dx, -T + (j + 0.5) * dx, -T + (k + 0.5) * dx};
        if (x.x > 0.0 && x.x < W && x.y > 0.0 && x.y < W && x.z > 0.0) continue;  // inside the tank
        lay.walls.push_back(x);
      }
  return make_liquid_3d(prm, lay, {dx, dx, dx}, H);
}

}  // namespace

SPH_SCENE(111, hydrostatic_tank_3d_scene) {
  SceneSpec s = scene_head("hydrostatic_tank_3d", "free-surface liquids (seed 001)",
                           "water at rest in a square 3D tank under gravity along -z; pressure against rho0 g (H - z)", 3,
                           UnitSystem::si());
  s.allow(Slot::Eos, {"tait", "dfsph"});
  s.allow(Slot::Walls, {"dummy"});
  hydrostatic_tank_head(s, 0.5, 0.05, 0.5, "tank width and length [m]", 2);
  s.build = [](const Params& prm, const SceneValues& v) {
    const double W = v.at("width"), H = v.at("depth"), dx = v.at("dx");
    SceneSetup out{tank_3d(prm, W, H, 1.2 * H, dx), {}, dx, lj_strength(kTankGravity, H)};
    out.domain.lo = {-0.2 * W, -0.2 * W, -0.2 * H};
    out.domain.hi = {1.2 * W, 1.2 * W, 1.3 * H};
    return out;
  };
  s.error_bounds = {{"L1_p_rel", 0.015}};  // measured to t = 0.5: 0.0102 (the start-up wave at t = 0.1)
  s.assumptions = {resolution("scene.dx", 1e-4, 0.05), weakly_compressible("depth", 1.0)};
  return s;
}

}  // namespace sph::scenes
