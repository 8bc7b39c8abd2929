// Set-ups several scenes share, so that a scene file states only what is its own: gas particles at
// given positions in a periodic box (the gas test boxes), the polytropic star of seed 003 §3.4.3 (its
// physics, its Lane-Emden solution and scales), the heads of the shock tubes, the strong-shock tests and the
// smooth 2D flows, and the two gas states of a shock tube (left | right).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "reference/lane_emden.h"
#include "sph/riemann.h"
#include "sph/scene.h"

namespace sph::scenes {

/// Gas at rest at positions x (their first dim coordinates are used), every particle of mass m [mass]
/// and smoothing length h [length], with specific internal energy u [energy/mass] where the stages
/// keep one. Callers change single particles' fields afterwards (velocities, masses, energies).
Particles gas_particles(const Params& prm, int dim, const std::vector<Vec3>& x, double m, double h, double u);

/// The box [lo, hi], periodic on its first dim axes and open on the others.
Domain periodic_box(int dim, const Vec3& lo, const Vec3& hi);

/// Mean spacing [length] of n particles filling a sphere of radius R [length]: (4 pi / 3 n)^(1/3) R.
double sphere_spacing(std::size_t n, double R);

/// The self-gravitating spheres' head (seed 003): category "gravity / self-gravitating spheres (seed 003)",
/// dimension 3, code units (G = M = R = 1).
SceneSpec sphere_head(std::string name, std::string description);

/// A self-gravitating gas sphere's common start: sphere_head with Barnes-Hut gravity (tree or direct
/// accepted), Monaghan viscosity alpha = 1, beta = 2, leapfrog, no walls. The caller adds the EOS.
SceneSpec gas_sphere_base(std::string name, std::string description);

/// The polytropic star scenes' common start (seed 003 §3.4.3; G = M = 1): gas_sphere_base with kernel
/// softening, gamma = 2 (n = 1) and K = 2/pi (R = 1). The caller adds the EOS and the rest.
SceneSpec polytrope_base(std::string name, std::string description);

/// The star of mass 1 with prm's gas.gamma (index n = 1/(gamma - 1)), gas.K and gravity.G: its Lane-Emden
/// solution and scales; throws ConfigError unless gamma > 4/3 (n < 3: a star of finite radius that
/// gravity can hold).
Polytrope star_of(const Params& prm);

/// A shock tube's common head: category "gas dynamics / shock tubes", the kernel, t_end with an output
/// every dt_out, the EOS options `eos`, no wall particles (the tube's walls are its domain's).
SceneSpec tube_scene(std::string name, std::string description, int dim, KernelType kernel, double t_end,
                     double dt_out, std::vector<std::string> eos);

/// The strong-shock tests' common start (Noh, Sedov): gas_test_scene with M4, gamma 5/3, alpha = 1 and
/// beta = 2, artificial conduction (alpha_u = 1), the energy equation (only "on"), leapfrog.
SceneSpec strong_shock_scene(std::string name, std::string category, std::string description, int dim);

/// The smooth 2D flows' common start (Gresho, Kelvin-Helmholtz): gas_test_scene with M6, gamma 5/3 and a
/// weak viscosity alpha = 0.1, beta = 0.2 (no shocks), no body force, start_params(n_side).
SceneSpec smooth_flow_scene(std::string name, std::string description, double n_side);

/// A tube's two states as the keys rho_l, v_l, p_l, rho_r, v_r, p_r (density in `density_unit`,
/// velocities along x).
std::vector<SceneParam> tube_state_params(const GasState& left, const GasState& right, const std::string& density_unit);

/// The left and right states those keys hold.
std::pair<GasState, GasState> tube_states(const SceneValues& v);

}  // namespace sph::scenes
