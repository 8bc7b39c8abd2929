// Building blocks of the liquid scenes: their common head, lattice blocks of fluid and wall particles for tanks and slopes.
// SI units. The inner surface of a wall is where its first layer of wall particles lies, half a
// spacing outside the fluid lattice: fluid particle centres start dx/2 inside it.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "sph/params.h"
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/vec.h"

namespace sph::scenes {

struct LiquidLayout {
  std::vector<Vec3> fluid;
  std::vector<Vec3> walls;
};

/// Fluid on a square lattice of spacing dx filling [x0, x1] x [y0, y1] (centres at x0 + (i + 1/2) dx).
void add_fluid_block(LiquidLayout& out, double x0, double x1, double y0, double y1, double dx);

/// The walls of an open-topped rectangular tank whose inner faces are x = 0, x = L and y = 0, up to
/// height H: Lennard-Jones walls are one line of particles at spacing dx/2 on the faces moved out by
/// dx/2 (seed 001 §7.2 puts the boundary particles on the wall); dummy walls are `layers` lattice rows
/// of spacing dx outside the faces, corners filled.
void add_tank_walls(LiquidLayout& out, double L, double H, double dx, WallType type, int layers);

/// One straight Lennard-Jones wall from a to b: particles at spacing ds on the segment.
void add_wall_line(LiquidLayout& out, Vec3 a, Vec3 b, double ds);

/// Dummy layers needed to fill a kernel's support below a wall: ceil(support * eta).
int dummy_layers(const Params& prm, int dim);

/// DFSPH (physics.eos = dfsph) holds the summation density at rho0: the kernel sum of the lattice, rho0
/// dx^d sum W, is rho0 times this factor (M4, h = 1.3 dx: 0.99995 in 2D, 0.99726 in 3D), and the masses
/// are divided by it. 1 for the other equations of state (their masses stay rho dx^d).
double lattice_density(const Params& prm, int dim);

/// The particles: fluid first (rho from a hydrostatic column of depth `surface - y` under gravity g if
/// g > 0, else rho0; mass rho dx^2), then walls (rho0, mass rho0 dx^2), every h = eta dx.
Particles make_liquid(const Params& prm, const LiquidLayout& layout, double dx, double surface, double g);

/// The physics every liquid scene starts from: continuity density with delta-SPH diffusion (delta =
/// 0.1), fixed h = 1.3 dx with the M4 kernel, Tait EOS for water (rho0 = 1000, gamma = 7) with sound speed
/// c0 and no tension, standard-corrected forces with Monaghan's Pi (alpha, beta = 0), the seed-001
/// predictor-corrector; no body force, no walls, no XSPH, no energy equation.
Params liquid_params(double c0, double alpha);

/// liquid_params for water of depth H in a tank under gravity g = 9.81 m/s^2: c0 = 10 sqrt(2 g H) (Mach
/// ~ 0.1 at the free-fall speed), uniform body force, dummy walls.
Params tank_params(double H, double alpha);

/// The liquid scenes' common head: 2D, SI units, category "free-surface liquids (seed 001)", Tait EOS
/// only, the wall options `walls` (none for a free drop). The caller sets the physics (liquid_params or
/// tank_params).
SceneSpec liquid_scene(std::string name, std::string description, std::vector<std::string> walls);

/// make_liquid in 3D with gravity along -z: the fluid's rho from the hydrostatic column below `surface`
/// (Tait inverted, g = -body.gz), mass rho a.x a.y a.z on a lattice of spacings a (walls rho0), every
/// h = eta (a.x a.y a.z)^(1/3).
Particles make_liquid_3d(const Params& prm, const LiquidLayout& layout, Vec3 a, double surface);

/// Lennard-Jones strength of seed 001 §7.2: D = 5 g H.
/// The reference guard of a weakly compressible liquid of height H = factor x scene value `key`: the
/// references are incompressible, which the liquid follows while c0 >= 10 sqrt(2 g H) (the defaults).
inline RefAssumption weakly_compressible(std::string key, double factor) {
  return {"c0 / sqrt(2 g H)", 10.0 * (1.0 - 1e-9), 1e300,
          "the reference is incompressible: c0 >= 10 times the fall speed sqrt(2 g H) keeps density changes near 1%",
          [key, factor](const Params& p, const SceneValues& v) {
            const double g = std::sqrt(p.body.gx * p.body.gx + p.body.gy * p.body.gy + p.body.gz * p.body.gz);
            return p.liquid.c0 / std::sqrt(2.0 * g * factor * v.at(key));
          }};
}

inline double lj_strength(double g, double H) { return 5.0 * g * H; }

/// g [m/s^2] of the tank scenes (tank_params' body force, the wall strength).
inline constexpr double kTankGravity = 9.81;

/// The values, defaults and reference of a tank of water at rest (hydrostatic_tank, hydrostatic_tank_3d):
/// scene values width, depth (both `size` by default) and dx; tank_params(size, 0.1) with gravity along
/// -y (up = 1) or -z (up = 2), run to t_end with an output every t_end / 10; P against rho0 g (H - y)
/// along the vertical axis (reference/hydrostatic_reference.h).
void hydrostatic_tank_head(SceneSpec& s, double size, double dx, double t_end, const char* width_help, int up);

/// The scene parameter "dx", the lattice spacing of fluid and walls [m] (default dx).
inline SceneParam spacing_param(double dx) { return {"dx", dx, 1e-4, 1.0, false, "particle spacing [m]", "m"}; }

/// A liquid scene's set-up from its layout: make_liquid with the hydrostatic column below `surface` under
/// prm's gravity, spacing dx and the Lennard-Jones strength for water that deep (the domain left default).
SceneSetup liquid_setup(const Params& prm, const LiquidLayout& layout, double dx, double surface);

/// Water of depth H filling [0, W] of an open tank of length L whose walls rise to height `top`
/// (add_fluid_block, add_tank_walls with prm's wall type), as liquid_setup returns it.
SceneSetup tank_setup(const Params& prm, double W, double H, double L, double top, double dx);

}  // namespace sph::scenes
