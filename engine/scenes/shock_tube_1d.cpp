// 1D shock tubes with equal-mass particles between mirror walls: Sod (Sod 1978; Toro §4.3.3) and the
// tube of seed 003 §3.3 (eqs. 3.52–3.61), with the exact Riemann solution as reference.
#include <cmath>
#include <memory>

#include "families.h"
#include "reference/riemann_reference.h"
#include "scene_util.h"
#include "sph/riemann.h"

namespace sph::scenes {
namespace {

struct TubeSetup {
  double x_lo, x_hi, x0;
  GasState left, right;
  std::size_t n_left, n_right;
};

TubeSetup tube_from(const SceneValues& v) {
  TubeSetup t{v.at("x_lo"), v.at("x_hi"), v.at("x0"), {v.at("rho_l"), 0.0, v.at("p_l")}, {v.at("rho_r"), 0.0, v.at("p_r")},
              static_cast<std::size_t>(v.at("n_left")), 0};
  // equal masses: n_right / n_left = (rho_r L_r) / (rho_l L_l)
  const double ratio = (t.right.rho * (t.x_hi - t.x0)) / (t.left.rho * (t.x0 - t.x_lo));
  t.n_right = static_cast<std::size_t>(std::llround(ratio * static_cast<double>(t.n_left)));
  if (t.n_right < 1) t.n_right = 1;
  return t;
}

SceneSetup build_tube(const SceneSpec& spec, const Params& prm, const SceneValues& v) {
  const TubeSetup t = tube_from(v);
  const std::size_t n = t.n_left + t.n_right;
  SceneSetup s{make_particles(prm, spec.dim, n), {}, (t.x0 - t.x_lo) / t.n_left, 0.0};
  Particles& p = s.particles;
  const double dxl = (t.x0 - t.x_lo) / t.n_left, dxr = (t.x_hi - t.x0) / t.n_right;
  const double m = t.left.rho * dxl;  // = rho_r dx_r up to the rounding of n_right
  const double eta = effective_eta(prm, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const bool left = i < t.n_left;
    const double dx = left ? dxl : dxr;
    p.x[0][i] = left ? t.x_lo + (i + 0.5) * dxl : t.x0 + (i - t.n_left + 0.5) * dxr;
    const GasState& g = left ? t.left : t.right;
    p[Field::Mass][i] = m;
    p[Field::H][i] = eta * dx;
    if (p.has(Field::Energy)) p[Field::Energy][i] = energy_from_pressure(g.p, g.rho, prm.gas.gamma);
    p.v[0][i] = g.v;
  }
  s.domain.lo = {t.x_lo, 0, 0};
  s.domain.hi = {t.x_hi, 1, 1};
  s.domain.bc = {Boundary::Wall, Boundary::Open, Boundary::Open};
  return s;
}

std::vector<SceneParam> tube_params(double x_lo, double x_hi, double rl, double pl, double rr, double pr, double nl) {
  return {
      {"n_left", nl, 4, 1e6, true, "particles left of the diaphragm (the right side gets equal masses)"},
      {"x_lo", x_lo, -1e3, 1e3, false, "left wall [length]"},
      {"x_hi", x_hi, -1e3, 1e3, false, "right wall [length]"},
      {"x0", 0.0, -1e3, 1e3, false, "diaphragm position [length]"},
      {"rho_l", rl, 1e-6, 1e6, false, "left density"},
      {"p_l", pl, 1e-9, 1e9, false, "left pressure"},
      {"rho_r", rr, 1e-6, 1e6, false, "right density"},
      {"p_r", pr, 1e-9, 1e9, false, "right pressure"},
  };
}

}  // namespace

SceneSpec sod_scene() {
  SceneSpec s;
  s.name = "sod";
  s.category = "gas dynamics / shock tubes";
  s.description = "1D Sod shock tube, rho,p = 1,1 | 0.125,0.1, gamma 1.4, t = 0.2, exact Riemann reference";
  s.dim = 1;
  s.defaults.kernel.type = KernelType::M4;
  s.defaults.time.t_end = 0.2;
  s.defaults.time.dt_out = 0.05;
  s.defaults.physics.conduction = Toggle::On;
  s.defaults.conduction.alpha_u = 1.0;
  s.allow(Slot::Eos, {"ideal_gas"});  // the Riemann reference is an ideal-gas solution
  s.allow(Slot::Walls, {"none"});
  s.params = tube_params(-0.5, 0.5, 1.0, 1.0, 0.125, 0.1, 400);
  s.convergence = {"scene.n_left", {100, 200, 400, 800, 1600}, -1.0};  // as tests/bench/sod_bench
  s.build = [s](const Params& p, const SceneValues& v) { return build_tube(s, p, v); };
  s.initial_pressure = [](const Vec3& r, const SceneValues& v) { return r.x < v.at("x0") ? v.at("p_l") : v.at("p_r"); };
  // the middle of the left state: far from the diaphragm and (mirror) wall
  s.density_anchor = [](const SceneValues& v) {
    return std::pair<std::size_t, double>(static_cast<std::size_t>(v.at("n_left")) / 2, v.at("rho_l"));
  };
  s.reference = [](const Params& p, const SceneValues& v) -> std::unique_ptr<Reference> {
    const TubeSetup t = tube_from(v);
    return make_riemann_reference(t.left, t.right, p.gas.gamma, t.x0, t.x_lo, t.x_hi);
  };
  return s;
}

SceneSpec castellanos_scene() {
  SceneSpec s = sod_scene();
  s.name = "shocktube_castellanos";
  s.description = "seed 003 tube: x in [-0.6,0.6], 1280 | 320 equal-mass particles, rho,p = 1,1 | 0.25,0.1795";
  s.params = tube_params(-0.6, 0.6, 1.0, 1.0, 0.25, 0.1795, 1280);
  s.defaults.time.integrator = IntegratorType::RK4;  // seed 003 integrates with RK4
  s.defaults.physics.conduction = Toggle::Off;       // seed 003 eqs. 3.58-3.61: viscosity only
  s.build = [s](const Params& p, const SceneValues& v) { return build_tube(s, p, v); };
  return s;
}

}  // namespace sph::scenes
