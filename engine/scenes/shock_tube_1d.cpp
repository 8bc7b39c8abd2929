// 1D shock tubes with equal-mass particles between mirror walls: Sod (Sod 1978; Toro §4.3.3) and the
// tube of seed 003 §3.3 (eqs. 3.52–3.61), with the exact Riemann solution as reference.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "reference/riemann_reference.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "shared_setups.h"
#include "sph/config.h"
#include "sph/riemann.h"

namespace sph::scenes {
namespace {

struct TubeSetup {
  double x_lo, x_hi, x0;
  GasState left, right;
  std::size_t n_left, n_right;
  double w = 0.0;  ///< width of the smoothed diaphragm (0: a sharp one) [length]
};

/// log cosh z without overflow: |z| + log(1 + e^{-2|z|}) - log 2.
double log_cosh(double z) { return std::abs(z) + std::log1p(std::exp(-2.0 * std::abs(z))) - std::log(2.0); }

/// Where the smoothed diaphragm has reached: s = (1 + tanh((x - x0)/w)) / 2, 0 on the left, 1 on the right
/// (a step at x0 for w = 0). Every initial field f(x) = f_L + (f_R - f_L) s(x) (Price 2008, J. Comput.
/// Phys. 227, 10040, §5.1, smooths the initial jump this way).
double blend(double x, const TubeSetup& t) {
  if (t.w <= 0.0) return x < t.x0 ? 0.0 : 1.0;
  return 0.5 * (1.0 + std::tanh((x - t.x0) / t.w));
}

GasState state_at(double x, const TubeSetup& t) {
  const double b = blend(x, t);
  return {t.left.rho + (t.right.rho - t.left.rho) * b, t.left.v + (t.right.v - t.left.v) * b,
          t.left.p + (t.right.p - t.left.p) * b};
}

/// Mass per unit area between x_lo and x of the smoothed density: rho_L (x - lo) + (rho_R - rho_L) S,
/// S = integral of s = ((x - lo) + w (log cosh((x - x0)/w) - log cosh((lo - x0)/w))) / 2.
double mass_below(double x, const TubeSetup& t) {
  const double S =
      0.5 * ((x - t.x_lo) + t.w * (log_cosh((x - t.x0) / t.w) - log_cosh((t.x_lo - t.x0) / t.w)));
  return t.left.rho * (x - t.x_lo) + (t.right.rho - t.left.rho) * S;
}

std::string text(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", x);
  return s;
}

/// The most particles a tube may hold: equal masses put n_left rho_r L_r / (rho_l L_l) on the right.
constexpr double kTubeParticles = 1e7;

TubeSetup tube_from(const SceneValues& v) {
  const auto [left, right] = tube_states(v);
  TubeSetup t{v.at("x_lo"), v.at("x_hi"), v.at("x0"), left, right, static_cast<std::size_t>(v.at("n_left")), 0,
              v.at("smooth")};
  if (!(t.x_lo < t.x0 && t.x0 < t.x_hi))
    throw ConfigError("scene.x0 = " + text(t.x0) + " must lie between scene.x_lo = " + text(t.x_lo) +
                      " and scene.x_hi = " + text(t.x_hi));
  // equal masses: n_right / n_left = (rho_r L_r) / (rho_l L_l), rounded; the right spacing is then
  // m / rho_r exactly and the right wall moves by less than half a spacing (the density stays exact)
  const double ratio = (t.right.rho * (t.x_hi - t.x0)) / (t.left.rho * (t.x0 - t.x_lo));
  if (!(ratio * static_cast<double>(t.n_left) <= kTubeParticles))
    throw ConfigError("equal masses would put " + text(ratio * static_cast<double>(t.n_left)) +
                      " particles right of the diaphragm (n_left rho_r (x_hi - x0) / (rho_l (x0 - x_lo)), at most 1e7): "
                      "lower scene.n_left, scene.rho_r or scene.x_hi");
  t.n_right = static_cast<std::size_t>(std::llround(ratio * static_cast<double>(t.n_left)));
  if (t.n_right < 1) t.n_right = 1;
  const double m = t.left.rho * (t.x0 - t.x_lo) / static_cast<double>(t.n_left);
  t.x_hi = t.x0 + static_cast<double>(t.n_right) * m / t.right.rho;
  return t;
}

SceneSetup build_tube(const SceneSpec& spec, const Params& prm, const SceneValues& v) {
  const TubeSetup t = tube_from(v);
  const std::size_t n = t.n_left + t.n_right;
  SceneSetup s{make_particles(prm, spec.dim, n), {}, (t.x0 - t.x_lo) / t.n_left, 0.0};
  Particles& p = s.particles;
  const double dxl = (t.x0 - t.x_lo) / t.n_left, dxr = (t.x_hi - t.x0) / t.n_right;
  const double m = t.left.rho * dxl;  // = rho_r dx_r (x_hi follows from it)
  const double eta = effective_eta(prm, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const bool left = i < t.n_left;
    double dx = left ? dxl : dxr;
    p.x[0][i] = left ? t.x_lo + (i + 0.5) * dxl : t.x0 + (i - t.n_left + 0.5) * dxr;
    if (t.w > 0.0) {  // equal masses on the smoothed density: particle i at mass_below(x) = (i + 1/2) m
      double lo = t.x_lo, hi = t.x_hi;
      const double target = (static_cast<double>(i) + 0.5) * m;
      for (int it = 0; it < 100 && hi - lo > 1e-15 * (t.x_hi - t.x_lo); ++it)
        (mass_below(0.5 * (lo + hi), t) < target ? lo : hi) = 0.5 * (lo + hi);
      p.x[0][i] = 0.5 * (lo + hi);
    }
    const GasState g = state_at(p.x[0][i], t);
    if (t.w > 0.0) dx = m / g.rho;
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

std::vector<SceneParam> tube_params(double x_lo, double x_hi, double x0, const GasState& l, const GasState& r, double nl) {
  std::vector<SceneParam> p = {
      {"n_left", nl, 4, 1e6, true, "particles left of the diaphragm (the right side gets equal masses)", "count"},
      {"x_lo", x_lo, -1e3, 1e3, false, "left wall [length]", "length"},
      {"x_hi", x_hi, -1e3, 1e3, false, "right wall [length]", "length"},
      {"x0", x0, -1e3, 1e3, false, "diaphragm position [length]", "length"}};
  for (SceneParam& q : tube_state_params(l, r, "mass/length")) p.push_back(std::move(q));
  p.push_back({"smooth", 0.0, 0.0, 1e3, false,
               "width w of a smoothed diaphragm: rho, v, P follow (1 + tanh((x - x0)/w)) / 2 between the two states "
               "(0: sharp); the reference stays the sharp problem's, which the run approaches once the waves are many "
               "w wide",
               "length"});
  return p;
}

/// The reference guard of a tube: its L1(rho) bound (measured at the defaults, x 1.5) and what the
/// Riemann solution assumes: a sharp diaphragm, at least the default resolution.
void tube_guard(SceneSpec& s, double l1_rho, double n_left) {
  s.error_bounds = {{"L1_rho", l1_rho}};
  s.assumptions = {resolution("scene.n_left", n_left, 1e6),
                   {"scene.smooth", 0.0, 0.0, "the exact solution is that of a sharp diaphragm", {}}};
}

}  // namespace

SPH_SCENE(10, sod_scene) {
  // ideal gas only: the Riemann reference is an ideal-gas solution
  SceneSpec s = tube_scene("sod", "1D Sod shock tube, rho,p = 1,1 | 0.125,0.1, gamma 1.4, t = 0.2, exact Riemann reference",
                           1, KernelType::M4, 0.2, 0.05, {"ideal_gas"});
  s.defaults.physics.conduction = Toggle::On;
  s.defaults.conduction.alpha_u = 1.0;
  // measured at the defaults: leapfrog 7e-6 (Toro 2: 9e-5); forward Euler 4.6e-3, cfl = 0.7 1.2e-2
  s.energy_bound = 1e-3;
  s.params = tube_params(-0.5, 0.5, 0.0, {1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 400);
  s.convergence = {"scene.n_left", {100, 200, 400, 800, 1600}, -1.0, ""};  // as tests/bench/sod_bench
  tube_guard(s, 4.5e-3, 400);  // L1(rho) measured at t = 0.2: 3.04e-3
  s.build = [s](const Params& p, const SceneValues& v) { return build_tube(s, p, v); };
  s.initial_pressure = [](const Vec3& r, const SceneValues& v) { return state_at(r.x, tube_from(v)).p; };
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

SPH_SCENE(20, castellanos_scene) {
  SceneSpec s = sod_scene();
  s.name = "shocktube_castellanos";
  s.description = "seed 003 tube: x in [-0.6,0.6], 1280 | 320 equal-mass particles, rho,p = 1,1 | 0.25,0.1795";
  s.params = tube_params(-0.6, 0.6, 0.0, {1.0, 0.0, 1.0}, {0.25, 0.0, 0.1795}, 1280);
  tube_guard(s, 1.2e-3, 1280);  // L1(rho) measured at t = 0.2: 7.8e-4
  s.defaults.time.integrator = IntegratorType::RK4;  // seed 003 integrates with RK4
  s.defaults.physics.conduction = Toggle::Off;       // seed 003 eqs. 3.58-3.61: viscosity only
  s.build = [s](const Params& p, const SceneValues& v) { return build_tube(s, p, v); };
  return s;
}

namespace {

/// A Riemann problem of the literature on the Sod set-up (M4, conduction, leapfrog, mirror walls).
SceneSpec riemann_variant(const char* name, const char* description, double x_lo, double x_hi, double x0,
                          GasState l, GasState r, double n_left, double t_end, double l1_rho) {
  SceneSpec s = sod_scene();
  s.name = name;
  s.description = description;
  s.params = tube_params(x_lo, x_hi, x0, l, r, n_left);
  set_run_times(s.defaults, t_end, t_end / 4.0);
  s.convergence.values = {100, 200, 400, 800};  // the strong waves cost many steps: 1600 takes 100 s with RK4
  tube_guard(s, l1_rho, n_left);
  s.build = [s](const Params& p, const SceneValues& v) { return build_tube(s, p, v); };
  return s;
}

}  // namespace

// Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics" (3rd ed.), Table 4.1, gamma = 1.4,
// with his diaphragm positions and end times; Lax (1954) as commonly posed. The walls are mirrors, not
// Toro's transmissive ends: where a state moves into or away from a wall, that wall launches a wave at
// t = 0. Each tube is long enough that no wall's wave (nor the fan) reaches the other waves before
// t_end, so the reference applies to the end (RiemannReference::valid_until; Toro's [0, 1] is widened
// for tests 1, 2 and 5 and Lax, with the particle spacing kept). The last number is the bound on L1(rho),
// 1.5 x its value measured at t_end (Lax 7.9e-3, tests 1-5: 4.2e-3, 0.031, 0.070, 0.069, 0.18).
SPH_SCENES(30, riemann_variant_scenes) {
  return {
      riemann_variant("lax", "Lax's tube, rho,v,p = 0.445,0.698,3.528 | 0.5,0,0.571, t = 0.14", -1.5, 0.5, 0.0,
                      {0.445, 0.698, 3.528}, {0.5, 0.0, 0.571}, 600, 0.14, 0.012),
      riemann_variant("toro1", "Toro test 1: a modified Sod tube with a sonic rarefaction, 1,0.75,1 | 0.125,0,0.1, t = 0.2",
                      -0.3, 1.0, 0.3, {1.0, 0.75, 1.0}, {0.125, 0.0, 0.1}, 600, 0.2, 6.5e-3),
      riemann_variant("toro2", "Toro test 2, \"123\": two rarefactions and a near vacuum, 1,-2,0.4 | 1,2,0.4, t = 0.15",
                      -0.1, 1.1, 0.5, {1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 240, 0.15, 0.045),
      riemann_variant("toro3", "Toro test 3: the left half of the blast wave, p = 1000 | 0.01, t = 0.012", 0.0, 1.0, 0.5,
                      {1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 200, 0.012, 0.1),
      riemann_variant("toro4", "Toro test 4: the right half of the blast wave, p = 0.01 | 100, t = 0.035", 0.0, 1.0, 0.4,
                      {1.0, 0.0, 0.01}, {1.0, 0.0, 100.0}, 160, 0.035, 0.1),
      riemann_variant("toro5", "Toro test 5: the collision of tests 3 and 4's shocks, t = 0.035", -0.4, 1.7, 0.8,
                      {5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 480, 0.035, 0.28),
  };
}

}  // namespace sph::scenes
