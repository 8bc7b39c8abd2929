// Dam breaks (seed 001 §7.2): a water column released in a tank under gravity, Tait EOS with
// c0 = 10 sqrt(2 g H) (weakly compressible: Mach ~ 0.1), continuity density with delta-SPH diffusion,
// Lennard-Jones (seed 001 eq. 60, D = 5 g H, p1 = 4, p2 = 2, r0 = dx) or dummy wall particles.
//  - dam_break: the classic column of width a and height 2a in a tank of length 4a (Martin & Moyce 1952;
//    Koshizuka & Oka 1996), against the measured surge fronts;
//  - dam_break_slope: seed 001's column released towards a downstream slope, with its fixed
//    dt = 0.15 ms; the water runs up, sloshes and comes to rest. The seed gives no dimensions; here a
//    0.3 m wide, 0.6 m high column, a flat floor 0.6 m long, then a 30 degree slope.
#include <cmath>
#include <numbers>

#include "liquid_tank.h"
#include "reference/dam_break_reference.h"
#include "scene_registration.h"
#include "scene_util.h"

namespace sph::scenes {
namespace {

/// The dam breaks' physics: tank_params with seed 001 §7.2's Lennard-Jones exponents (when chosen).
Params liquid_defaults(double H, double alpha = 0.1) {
  Params d = tank_params(H, alpha);
  d.walls.p1 = 4.0;
  d.walls.p2 = 2.0;
  return d;
}

}  // namespace

SPH_SCENE(90, dam_break_scene) {
  SceneSpec s = liquid_scene(
      "dam_break",
      "water column a x 2a collapses in a 4a tank; surge front vs Martin & Moyce 1952, Koshizuka & Oka 1996",
      {"dummy", "lennard_jones"});
  s.params = {{"a", 1.0, 0.01, 100.0, false, "column width a [m] (height 2a, tank length 4a)", "m"},
              spacing_param(0.025)};
  // alpha = 0.2: the artificial viscosity between the fluid and the wall particles is the only wall
  // friction the scheme has, and the leading edge is a layer a few particles thick. Measured at dx = a/40
  // (front against the nearer data set, T <= 2.5): alpha = 0.1 runs ahead by up to 7.0%, 0.2 by up to
  // 4.3%, 0.3 by up to 3.6%. The experiment's floor is no-slip.
  s.defaults = liquid_defaults(2.0 * s.params[0].value, 0.2);
  set_run_times(s.defaults, 0.7, 0.05);  // T = t sqrt(2g/a) = 3.1 for a = 1 m
  s.build = [](const Params& prm, const SceneValues& v) {
    const double a = v.at("a"), dx = v.at("dx"), L = 4.0 * a, H = 2.0 * a;
    SceneSetup out = tank_setup(prm, a, H, L, 1.25 * H, dx);
    out.domain.lo = {-0.1 * a, -0.1 * a, 0.0};
    out.domain.hi = {L + 0.1 * a, 1.25 * H, 1.0};
    return out;
  };
  s.reference = [](const Params& prm, const SceneValues& v) {
    return make_dam_break_reference(v.at("a"), v.at("dx"), -prm.body.gy);
  };
  s.error_bounds = {{"err_data", 0.065}};  // measured to t = 0.7: 0.043
  // `sph converge`/`sph bench`: the front against the nearer series at t = 0.6 (T = 2.66), dx = a/20 ... a/40
  s.convergence = {"scene.dx", {0.05, 0.1 / 3.0, 0.025}, 0.6, "err_data"};
  s.assumptions = {{"scene.dx / scene.a", 0.0, 0.025, "the error bound was measured at dx = a/40 or finer",
                    [](const Params&, const SceneValues& v) { return v.at("dx") / v.at("a"); }},
                   weakly_compressible("a", 2.0)};
  return s;
}

SPH_SCENE(100, dam_break_slope_scene) {
  SceneSpec s = liquid_scene(
      "dam_break_slope",
      "seed 001 §7.2: a column released towards a 30 degree slope, Lennard-Jones walls, dt = 0.15 ms; comes to rest",
      {"lennard_jones"});
  s.params = {{"width", 0.3, 0.01, 10.0, false, "column width [m]", "m"},
              {"height", 0.6, 0.01, 10.0, false, "column height H [m]", "m"},
              {"floor", 0.6, 0.0, 100.0, false, "length of the flat floor before the slope [m]", "m"},
              {"angle", 30.0, 5.0, 80.0, false, "slope angle [degrees]", "degrees"},
              spacing_param(0.02)};
  s.defaults = liquid_defaults(0.6);
  s.defaults.physics.walls = WallType::LennardJones;  // seed 001 eq. 60
  // The standard formulation with XSPH (seed 001 eqs. 44-47). With the corrected gradients and these
  // walls, the thin film running back along the floor loses density without limit (rho = 226 at
  // t = 1.9 s, dx = 0.02: no tension can pull it back, and the walls are not in the sums) until the run
  // blows up (detected); at dx = 0.03 and 0.04 they come to rest too.
  s.defaults.physics.force = ForceType::Standard;
  s.defaults.physics.xsph = Toggle::On;
  s.defaults.time.dt = 1.5e-4;                         // seed 001 §7.2: dt = 0.15 ms
  set_run_times(s.defaults, 5.0, 0.1);                 // the seed's water is at rest by t = 4.5 s
  s.build = [](const Params& prm, const SceneValues& v) {
    const double W = v.at("width"), H = v.at("height"), F = v.at("floor"), dx = v.at("dx");
    const double th = v.at("angle") * std::numbers::pi / 180.0;
    const double top = 3.0 * H;  // height of the walls: the run-up never overtops the slope
    const double slope_len = top / std::sin(th);
    LiquidLayout lay;
    add_fluid_block(lay, 0.0, W, 0.0, H, dx);
    const double o = 0.5 * dx, ds = 0.5 * dx;                    // as add_tank_walls: lines dx/2 outside
    const Vec3 corner{F + o * std::tan(0.5 * th), -o, 0.0};      // where the floor line meets the slope line
    add_wall_line(lay, {-o, top, 0}, {-o, -o, 0}, ds);          // left wall
    add_wall_line(lay, {-o + ds, -o, 0}, corner, ds);            // floor
    add_wall_line(lay, corner, corner + Vec3{std::cos(th), std::sin(th), 0} * slope_len, ds);  // slope
    SceneSetup out = liquid_setup(prm, lay, dx, H);
    out.domain.lo = {-0.1 * H, -0.1 * H, 0.0};
    out.domain.hi = {F + top / std::tan(th) + 0.1 * H, top, 1.0};
    return out;
  };
  return s;
}

}  // namespace sph::scenes
