// The declaration of every run parameter (see sph/param_table.h), group by group in the table's order
// (the order of `sph params`, the GUI and the scene assets); how one entry is made: params/param_entry.h,
// which stage owns each: params/param_owners.h.
#include "sph/param_table.h"
#include "params/param_entry.h"
#include "params/param_owners.h"

#include <array>
#include <cmath>
#include <cstdlib>

namespace sph {
namespace {

using namespace param_entry;
using namespace param_owner;

/// The slots first, in pipeline order; "h_mode" was the smoothing slot's flat key.
void add_slots(std::vector<ParamInfo>& t) {
  static std::array<std::string, kSlotCount> slot_keys;  // ParamInfo keeps views of them
  for (const SlotInfo& s : slot_table()) {
    std::string& key = slot_keys[static_cast<std::size_t>(s.slot)];
    key = "physics." + std::string(s.key);
    t.push_back(slot(s, key, s.slot == Slot::Smoothing ? "h_mode" : ""));
  }
}

/// The kernel, the density options and the smoothing-length solve.
void add_kernel(std::vector<ParamInfo>& t) {
  using K = KernelType;
  t.push_back(choice<K>({"kernel.type", "choice", "smoothing kernel W (seed 000 eqs. 3.2.6-3.2.9)", "kernel", kKernel},
                        [](Params& p) -> K& { return p.kernel.type; },
                        {K::M4, K::M5, K::M6, K::Gaussian, K::WendlandC2, K::WendlandC4}));
  t.push_back(real({"kernel.eta", "dimensionless",
                    "h = eta (m/rho)^(1/d) (seed 000 eq. 3.3.33); 0 = the kernel's default", "eta", kKernel},
                   [](Params& p) -> double& { return p.kernel.eta; }, 0.0, 4.0));
  t.push_back(integer({"density.reinit_every", "steps",
                       "re-initialise rho by the MLS-corrected kernel sum every this many steps (seed 001 eqs. "
                       "19-22; Colagrossi & Landrini 2003); 0 = never",
                       "", kContinuity, true},
                      [](Params& p) -> int& { return p.density.reinit_every; }, 0, 100000));
  t.push_back(real({"density.diffusion", "dimensionless",
                    "delta of the density diffusion 2 delta h c0 sum_b V_b (rho_a - rho_b) dW/dr / r (Molteni & "
                    "Colagrossi 2009): damps the pressure noise of weakly compressible flows; 0 = off",
                    "", kContinuity, true},
                   [](Params& p) -> double& { return p.density.diffusion; }, 0.0, 1.0));
  t.push_back(real({"h.tol", "dimensionless", "Newton-Raphson relative tolerance on h (seed 000 eq. 3.5.1)", "h_tol",
                    kVariableH, true},
                   [](Params& p) -> double& { return p.h.tol; }, 1e-15, 1e-2));
  t.push_back(integer({"h.max_iter", "iterations", "Newton-Raphson iteration cap per particle", "h_max_iter",
                       kVariableH, true},
                      [](Params& p) -> int& { return p.h.max_iter; }, 1, 1000));
}

/// The equations of state: ideal gas, isothermal, polytropic and Tait.
void add_eos(std::vector<ParamInfo>& t) {
  t.push_back(real({"gas.gamma", "dimensionless",
                    "adiabatic index, P = (gamma-1) rho u (seed 000 eq. 3.3.23); polytropic: gamma = 1 + 1/n", "gamma",
                    kGammaOwner, false},
                   [](Params& p) -> double& { return p.gas.gamma; }, 1.0001, 10.0));
  t.push_back(real({"gas.cs", "length/time", "isothermal sound speed, P = cs^2 rho", "", kIsothermal, false},
                   [](Params& p) -> double& { return p.gas.cs; }, 1e-9, 1e9));
  t.push_back(real({"gas.K", "pressure/density^gamma", "polytropic constant of P = K rho^gamma (seed 003 eq. 3.72)",
                    "", kPolytropic, false},
                   [](Params& p) -> double& { return p.gas.K; }, 1e-12, 1e12));
  t.push_back(real({"liquid.rho0", "mass/length^d", "reference density of the liquid (Tait: seed 001 eq. 3; DFSPH)", "",
                    kLiquid, false},
                   [](Params& p) -> double& { return p.liquid.rho0; }, 1e-9, 1e9));
  t.push_back(real({"liquid.c0", "length/time",
                    "sound speed at rho0: B = rho0 c0^2/gamma (seed 001 §2: c^2 = gamma k/rho0 with k = B)", "",
                    kTait, true},
                   [](Params& p) -> double& { return p.liquid.c0; }, 1e-9, 1e9));
  t.push_back(real({"liquid.gamma", "dimensionless", "Tait exponent, 7 for water (seed 001 eq. 3)", "", kTait, true},
                   [](Params& p) -> double& { return p.liquid.gamma; }, 1.0, 20.0));
  t.push_back(real({"liquid.p0", "pressure", "background pressure added to the Tait pressure", "", kTait, true},
                   [](Params& p) -> double& { return p.liquid.p0; }, -1e12, 1e12));
  t.push_back(real({"liquid.p_min", "pressure",
                    "floor of the Tait pressure: no more tension than this (water cavitates near -1e5 Pa gauge)", "",
                    kTait, true},
                   [](Params& p) -> double& { return p.liquid.p_min; }, -1e300, 1e12));
  t.push_back(real({"liquid.dfsph_eta", "dimensionless",
                    "DFSPH: the density solve stops when the mean compression (rho* - rho0)/rho0 is at most this", "",
                    kDfsph, true},
                   [](Params& p) -> double& { return p.liquid.dfsph_eta; }, 1e-7, 0.1));
  t.push_back(real({"liquid.dfsph_eta_div", "dimensionless",
                    "DFSPH: the divergence solve stops when the mean dt (Drho/Dt)/rho0 is at most this", "", kDfsph, true},
                   [](Params& p) -> double& { return p.liquid.dfsph_eta_div; }, 1e-7, 0.1));
  t.push_back(integer({"liquid.dfsph_max_iter", "iterations",
                       "DFSPH: cap on each pressure solve's iterations (applications of the pressure operator)", "",
                       kDfsph, true},
                      [](Params& p) -> int& { return p.liquid.dfsph_max_iter; }, 1, 10000));
  t.push_back(choice<DfsphSolverType>({"liquid.dfsph_solver", "choice",
                                       "DFSPH: how the pressure solves iterate: jacobi (Bender & Koschier's relaxed "
                                       "Jacobi) or bicgstab (also removes a pressure error smooth over the liquid)",
                                       "", kDfsph, true},
                                      [](Params& p) -> DfsphSolverType& { return p.liquid.dfsph_solver; },
                                      {DfsphSolverType::Jacobi, DfsphSolverType::BiCGStab}));
}

/// The artificial and physical viscosities and the viscosity switch.
void add_viscosity(std::vector<ParamInfo>& t) {
  t.push_back(real({"visc.alpha", "dimensionless", "artificial viscosity, linear term (seed 003 eq. 3.16; seed 001 eq. 41)",
                    "alpha", kConstantAlpha, true},
                   [](Params& p) -> double& { return p.visc.alpha; }, 0.0, 10.0));
  t.push_back(real({"visc.beta", "dimensionless", "artificial viscosity, quadratic term (seed 003 eq. 3.16)", "beta",
                    kMonaghan, true},
                   [](Params& p) -> double& { return p.visc.beta; }, 0.0, 20.0));
  t.push_back(choice<ViscSwitch>({"visc.switch", "choice",
                                  "alpha per particle: none (constant visc.alpha), balsara (visc.alpha times |div v|/"
                                  "(|div v| + |curl v|), Balsara 1995) or cullen_dehnen (raised ahead of shocks, "
                                  "decaying behind them: Cullen & Dehnen 2010)",
                                  "", kSwitchable, true},
                                 [](Params& p) -> ViscSwitch& { return p.physics.visc_switch; },
                                 {ViscSwitch::None, ViscSwitch::Balsara, ViscSwitch::CullenDehnen}));
  t.push_back(real({"visc.alpha_min", "dimensionless", "Cullen-Dehnen switch: alpha far from shocks", "",
                    kCullenDehnen, true},
                   [](Params& p) -> double& { return p.visc.alpha_min; }, 0.0, 10.0));
  t.push_back(real({"visc.alpha_max", "dimensionless",
                    "Cullen-Dehnen switch: alpha at a shock (the quadratic term is beta alpha / alpha_max)", "",
                    kCullenDehnen, true},
                   [](Params& p) -> double& { return p.visc.alpha_max; }, 1e-3, 10.0));
  t.push_back(real({"visc.decay", "dimensionless",
                    "Cullen-Dehnen switch: alpha decays on tau = H / (decay c) behind a shock, H the kernel's support "
                    "radius (Cullen & Dehnen 2010: 0.05-0.2)", "", kCullenDehnen, true},
                   [](Params& p) -> double& { return p.visc.decay; }, 1e-3, 10.0));
  t.push_back(real({"visc.eps", "dimensionless", "eta^2 = eps h^2 regularises 1/r^2 (seed 001 eq. 42: 0.01)",
                    "visc_eps", kAnyViscosity, true},
                   [](Params& p) -> double& { return p.visc.eps; }, 1e-6, 1.0));
  t.push_back(real({"visc.nu", "length^2/time", "kinematic viscosity of the Laplacian viscosity (seed 004; Morris 1997)",
                    "", kLaplacian, true},
                   [](Params& p) -> double& { return p.visc.nu; }, 0.0, 1e6));
}

/// Conduction, XSPH and the body forces.
void add_conduction_xsph_body(std::vector<ParamInfo>& t) {
  t.push_back(real({"conduction.alpha_u", "dimensionless", "artificial thermal conductivity (Price 2008)", "alpha_u",
                    kConduction, true},
                   [](Params& p) -> double& { return p.conduction.alpha_u; }, 0.0, 10.0));
  t.push_back(real({"xsph.eps", "dimensionless", "XSPH strength epsilon (seed 001 eq. 45: 0.5)", "", kXsph, true},
                   [](Params& p) -> double& { return p.xsph.eps; }, 0.0, 1.0));
  t.push_back(real({"body.tau", "time", "damping time of a = -v/tau (relaxation to equilibrium)", "", kDamping, true},
                   [](Params& p) -> double& { return p.body.tau; }, 1e-9, 1e9));
  t.push_back(real({"body.gx", "length/time^2", "uniform body force, x component", "", kBody, true},
                   [](Params& p) -> double& { return p.body.gx; }, -1e6, 1e6));
  t.push_back(real({"body.gy", "length/time^2", "uniform body force, y component", "", kBody, true},
                   [](Params& p) -> double& { return p.body.gy; }, -1e6, 1e6));
  t.push_back(real({"body.gz", "length/time^2", "uniform body force, z component", "", kBody, true},
                   [](Params& p) -> double& { return p.body.gz; }, -1e6, 1e6));
}

/// Self-gravity: G, softening and the Barnes-Hut tree.
void add_gravity(std::vector<ParamInfo>& t) {
  t.push_back(real({"gravity.G", "length^3/(mass time^2)", "gravitational constant (4 pi^2 in AU, solar masses, years)",
                    "G", kGravity, true},
                   [](Params& p) -> double& { return p.gravity.G; }, 0.0, 1e12));
  t.push_back(choice<Softening>({"gravity.softening", "choice",
                                 "short-range softening: Plummer (seed 003 eq. 2.43) or the SPH kernel of each particle's "
                                 "h with its grad-h term (Price & Monaghan 2007), or without it (energy leaks as h changes)",
                                 "", kGravity, true},
                                [](Params& p) -> Softening& { return p.gravity.softening; },
                                {Softening::Plummer, Softening::Kernel, Softening::KernelNoGradH}));
  t.push_back(real({"gravity.eps", "length", "Plummer softening length eps (seed 003 eq. 2.43); 0 = point masses",
                    "eps", kPlummer, true},
                   [](Params& p) -> double& { return p.gravity.eps; }, 0.0, 1e12));
  t.push_back(real({"gravity.theta", "dimensionless",
                    "Barnes-Hut opening angle: a cell is used whole when its size < theta x distance; 0 = exact",
                    "theta", kTree, true},
                   [](Params& p) -> double& { return p.gravity.theta; }, 0.0, 1.2));
  t.push_back(real({"gravity.tol", "dimensionless",
                    "Barnes-Hut relative guard: a cell is used whole only if its dropped octupole term M bmax^3/d^5 is "
                    "below tol x |a| of the particle (so the error stays small where |a| is small); 0 = plain theta",
                    "tol", kTree, true},
                   [](Params& p) -> double& { return p.gravity.tol; }, 0.0, 0.1));
  t.push_back(real({"gravity.fmm_theta", "dimensionless",
                    "fast multipole opening criterion: cells A and B interact as expansions when (r_A + r_B) < theta x "
                    "their distance, r the largest distance of a cell's particles from its centre of mass (Dehnen 2002)",
                    "", kFmm, true},
                   [](Params& p) -> double& { return p.gravity.fmm_theta; }, 0.05, 0.95));
  t.push_back(real({"gravity.fmm_tol", "dimensionless",
                    "fast multipole relative guard: cells interact as expansions only if the estimated error M_A "
                    "rho^P / (R^2 (1 - rho)^2), rho = (r_A + r_B)/R, is below tol x the smallest |a| of B; 0 = off",
                    "", kFmm, true},
                   [](Params& p) -> double& { return p.gravity.fmm_tol; }, 0.0, 0.1));
  t.push_back(integer({"gravity.fmm_order", "dimensionless",
                       "fast multipole expansion order P (multipoles and local expansions to order P; 2 = quadrupole)",
                       "", kFmm, true},
                      [](Params& p) -> int& { return p.gravity.fmm_order; }, 1, 6));
}

/// The finite pointset method, the Lennard-Jones walls and the kernel corrections.
void add_fpm_walls_corrections(std::vector<ParamInfo>& t) {
  t.push_back(real({"fpm.alpha", "dimensionless", "MLS weight exp(-alpha r^2/h^2) (seed 002 eq. 9; the seed uses 8)",
                    "alpha", kFpm, true},
                   [](Params& p) -> double& { return p.fpm.alpha; }, 0.0, 20.0));
  t.push_back(real({"fpm.eps", "length^2/time", "Burgers viscosity epsilon (seed 002 eq. 6a)", "eps", kFpmViscous, true},
                   [](Params& p) -> double& { return p.fpm.eps; }, 0.0, 10.0));
  t.push_back(choice<PointControl>({"fpm.control", "choice",
                                    "point control (seed 002 Note 3.2): reinterpolate u onto the initial points after "
                                    "every step; merge_split (points closer than dx/2 merge, gaps wider than 3 dx/2 "
                                    "get a midpoint, values linearly interpolated); or none (the points move freely)",
                                    "", kFpm, true},
                                   [](Params& p) -> PointControl& { return p.fpm.control; },
                                   {PointControl::Reinterpolate, PointControl::MergeSplit, PointControl::None}));
  t.push_back(real({"walls.D", "length^2/time^2", "Lennard-Jones strength (seed 001 eq. 60: D ~ 5 g H); 0 = the scene's",
                    "", kLJ, true},
                   [](Params& p) -> double& { return p.walls.D; }, 0.0, 1e12));
  t.push_back(real({"walls.p1", "dimensionless", "Lennard-Jones repulsive exponent p1 > p2 (seed 001: 4)", "", kLJ, true},
                   [](Params& p) -> double& { return p.walls.p1; }, 1.0, 24.0));
  t.push_back(real({"walls.p2", "dimensionless", "Lennard-Jones attractive exponent (seed 001: 2)", "", kLJ, true},
                   [](Params& p) -> double& { return p.walls.p2; }, 0.0, 23.0));
  t.push_back(real({"walls.r0", "length", "Lennard-Jones cut-off (seed 001: the initial spacing); 0 = the scene's", "",
                    kLJ, true},
                   [](Params& p) -> double& { return p.walls.r0; }, 0.0, 1e6));
  t.push_back(real({"walls.friction", "dimensionless",
                    "share of the viscosity acting between fluid and dummy-wall particles: 1 = no-slip walls, "
                    "0 = free-slip (Adami et al. 2012); below 1 a fast impact can push fluid through the walls",
                    "", kWallFriction, true},
                   [](Params& p) -> double& { return p.walls.friction; }, 0.0, 1.0));
  t.push_back(real({"correction.min_rcond", "dimensionless",
                    "below this reciprocal condition number a kernel or gradient correction falls back to order 0", "",
                    kCorrected, true},
                   [](Params& p) -> double& { return p.correction.min_rcond; }, 0.0, 1.0));
}

/// Time integration and output.
void add_time(std::vector<ParamInfo>& t) {
  using I = IntegratorType;
  t.push_back(choice<I>({"time.integrator", "choice", "time integrator (seed 000 App. A; seed 001 eqs. 56-59)",
                         "integrator", kIntegrated},
                        [](Params& p) -> I& { return p.time.integrator; },
                        {I::Euler, I::RK4, I::Leapfrog, I::PredictorCorrector}));
  t.push_back(real({"time.dt", "time", "fixed timestep; 0 = adaptive from cfl", "dt"},
                   [](Params& p) -> double& { return p.time.dt; }, 0.0, 1e6));
  t.push_back(real({"time.cfl", "dimensionless", "Courant factor: dt = cfl min(h/v_sig, sqrt(h/|a|), stage limits)",
                    "cfl"},
                   [](Params& p) -> double& { return p.time.cfl; }, 1e-4, 2.0));
  t.push_back(integer({"time.levels", "levels",
                       "individual time steps: each particle steps with dt_max / 2^k, k < levels (leapfrog, "
                       "adaptive dt); 1 = one global step"},
                      [](Params& p) -> int& { return p.time.levels; }, 1, 30));
  t.push_back(real({"time.t_end", "time", "end time of a run", "t_end"},
                   [](Params& p) -> double& { return p.time.t_end; }, 0.0, 1e9));
  t.push_back(real({"time.dt_out", "time", "interval between particle outputs; 0 = end only", "dt_out"},
                   [](Params& p) -> double& { return p.time.dt_out; }, 0.0, 1e9));
}

std::vector<ParamInfo> build() {
  std::vector<ParamInfo> t;
  add_slots(t);
  add_kernel(t);
  add_eos(t);
  add_viscosity(t);
  add_conduction_xsph_body(t);
  add_gravity(t);
  add_fpm_walls_corrections(t);
  add_time(t);
  return t;
}

}  // namespace

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(out);
}

const std::vector<ParamInfo>& param_table() {
  static const std::vector<ParamInfo> table = build();
  return table;
}

const ParamInfo* find_param(std::string_view key) {
  for (const auto& p : param_table())
    if (p.key == key || (!p.alias.empty() && p.alias == key)) return &p;
  return nullptr;
}

}  // namespace sph
