// Set-ups several scenes share (see shared_setups.h).
#include "shared_setups.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "scene_util.h"
#include "start_positions.h"
#include "sph/config.h"

namespace sph::scenes {

Particles gas_particles(const Params& prm, int dim, const std::vector<Vec3>& x, double m, double h, double u) {
  Particles p = make_particles(prm, dim, x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double c[3] = {x[i].x, x[i].y, x[i].z};
    for (int k = 0; k < dim; ++k) p.x[k][i] = c[k];
    p[Field::Mass][i] = m;
    p[Field::H][i] = h;
    if (p.has(Field::Energy)) p[Field::Energy][i] = u;
  }
  return p;
}

Domain periodic_box(int dim, const Vec3& lo, const Vec3& hi) {
  Domain d;
  d.lo = {lo.x, lo.y, lo.z};
  d.hi = {hi.x, hi.y, hi.z};
  for (int k = 0; k < 3; ++k) d.bc[k] = k < dim ? Boundary::Periodic : Boundary::Open;
  return d;
}

double sphere_spacing(std::size_t n, double R) {
  return std::cbrt(4.0 * std::numbers::pi / 3.0 / static_cast<double>(n)) * R;
}

SceneSpec sphere_head(std::string name, std::string description) {
  return scene_head(std::move(name), "gravity / self-gravitating spheres (seed 003)", std::move(description), 3);
}

SceneSpec gas_sphere_base(std::string name, std::string description) {
  SceneSpec s = sphere_head(std::move(name), std::move(description));
  Params& d = s.defaults;
  d.physics.gravity = GravityType::Tree;
  d.visc.alpha = 1.0;
  d.visc.beta = 2.0;
  d.time.integrator = IntegratorType::Leapfrog;
  s.allow(Slot::Walls, {"none"});
  s.allow(Slot::Gravity, {"tree", "direct", "fmm"});
  return s;
}

SceneSpec polytrope_base(std::string name, std::string description) {
  SceneSpec s = gas_sphere_base(std::move(name), std::move(description));
  s.defaults.gravity.softening = Softening::Kernel;
  s.defaults.gas.gamma = 2.0;  // n = 1
  s.defaults.gas.K = 2.0 / std::numbers::pi;
  return s;
}

Polytrope star_of(const Params& prm) {
  if (!(prm.gas.gamma > 4.0 / 3.0))
    throw ConfigError("gas.gamma = " + std::to_string(prm.gas.gamma) + ": a polytrope needs gamma > 4/3 (n < 3)");
  return Polytrope(1.0 / (prm.gas.gamma - 1.0), 1.0, prm.gas.K, prm.gravity.G);
}

SceneSpec tube_scene(std::string name, std::string description, int dim, KernelType kernel, double t_end,
                     double dt_out, std::vector<std::string> eos) {
  SceneSpec s = scene_head(std::move(name), "gas dynamics / shock tubes", std::move(description), dim);
  s.defaults.kernel.type = kernel;
  set_run_times(s.defaults, t_end, dt_out);
  s.allow(Slot::Eos, std::move(eos));
  s.allow(Slot::Walls, {"none"});
  return s;
}

SceneSpec strong_shock_scene(std::string name, std::string category, std::string description, int dim) {
  SceneSpec s = gas_test_scene(std::move(name), std::move(category), std::move(description), dim, KernelType::M4,
                               5.0 / 3.0, 1.0, 2.0);
  Params& d = s.defaults;
  d.physics.conduction = Toggle::On;
  d.conduction.alpha_u = 1.0;
  d.time.integrator = IntegratorType::Leapfrog;
  s.allow(Slot::Energy, {"on"});
  return s;
}

SceneSpec smooth_flow_scene(std::string name, std::string description, double n_side) {
  SceneSpec s = gas_test_scene(std::move(name), "gas dynamics / multidimensional tests", std::move(description), 2,
                               KernelType::M6, 5.0 / 3.0, 0.1, 0.2);
  s.allow(Slot::BodyForce, {"none"});
  s.params = start_params(n_side);
  return s;
}

std::vector<SceneParam> tube_state_params(const GasState& left, const GasState& right, const std::string& density_unit) {
  return {{"rho_l", left.rho, 1e-6, 1e6, false, "left density", density_unit},
          {"v_l", left.v, -1e3, 1e3, false, "left velocity along x", "length/time"},
          {"p_l", left.p, 1e-9, 1e9, false, "left pressure", "pressure"},
          {"rho_r", right.rho, 1e-6, 1e6, false, "right density", density_unit},
          {"v_r", right.v, -1e3, 1e3, false, "right velocity along x", "length/time"},
          {"p_r", right.p, 1e-9, 1e9, false, "right pressure", "pressure"}};
}

std::pair<GasState, GasState> tube_states(const SceneValues& v) {
  return {{v.at("rho_l"), v.at("v_l"), v.at("p_l")}, {v.at("rho_r"), v.at("v_r"), v.at("p_r")}};
}

}  // namespace sph::scenes
