// Run parameters: a plain value struct with defaults and units, grouped by the stage that uses them.
// The engine steps on a const Params&; the GUI edits its own copy and hands it over whole. Every field
// is declared once in param_table.cpp (key GROUP.NAME, unit, range, stage), which drives the JSON key,
// the --set override and the GUI widget, and refuses a parameter whose stage the scene does not run.
#pragma once
#include <string>

#include "sph/physics.h"

namespace sph {

/// Smoothing kernels of seed 000 eqs. 3.2.6–3.2.9 plus Wendland C2/C4 (Wendland 1995; Dehnen & Aly 2012).
enum class KernelType { M4, M5, M6, Gaussian, WendlandC2, WendlandC4 };
/// Time integrators: explicit Euler, RK4 (seed 000 App. A), leapfrog kick-drift-kick,
/// and the modified-Euler predictor-corrector of seed 001 eqs. 56–59.
enum class IntegratorType { Euler, RK4, Leapfrog, PredictorCorrector };
/// How self-gravity is softened at short range.
enum class Softening {
  Plummer,  ///< -G m x / (|x|^2 + eps^2)^(3/2) (seed 003 eq. 2.43, denominator corrected)
  Kernel,   ///< the mass of each particle spread like the SPH kernel of its h, with the grad-h (zeta) term
            ///< that conserves energy as h changes (Price & Monaghan 2007)
  KernelNoGradH,  ///< the kernel law without its grad-h term: energy leaks as h changes
};
/// Whether the law spreads each mass like the SPH kernel of its h.
inline bool kernel_softened(Softening s) { return s != Softening::Plummer; }

struct KernelParams {
  KernelType type = KernelType::M4;  ///< kernel family (live: takes effect at the next step)
  double eta = 0.0;                  ///< h = eta (m/rho)^(1/d); 0 = the kernel's default [dimensionless]
  bool operator==(const KernelParams&) const = default;
};

/// The continuity density (physics.density = continuity).
struct DensityParams {
  int reinit_every = 0;  ///< every this many steps, rho is re-initialised by the MLS-corrected kernel sum
                         ///< (seed 001 eqs. 19-22; Colagrossi & Landrini 2003); 0 = never
  double diffusion = 0.0;  ///< delta of the density diffusion term (Molteni & Colagrossi 2009) [dimensionless]
  bool operator==(const DensityParams&) const = default;
};

/// Newton-Raphson solve of h (physics.smoothing = variable).
struct SmoothingParams {
  double tol = 1e-6;  ///< relative tolerance on h [dimensionless]: 1e-6 against 1e-10 changes Sod L1 by 3e-6 (relative)
  int max_iter = 30;   ///< iteration cap before the bisection fallback
  bool operator==(const SmoothingParams&) const = default;
};

struct TimeParams {
  IntegratorType integrator = IntegratorType::Leapfrog;
  double dt = 0.0;       ///< fixed timestep [time]; 0 = adaptive with cfl
  double cfl = 0.3;      ///< Courant factor: dt = cfl min(h/v_sig, sqrt(h/|a|), stage limits) [dimensionless]
  double t_end = 0.2;    ///< end time of a run [time]
  double dt_out = 0.05;  ///< interval between particle outputs [time]
  /// Individual time steps: each particle on a power-of-two level of the largest step, at most this
  /// many levels (leapfrog with an adaptive step); 1 = one global step.
  int levels = 1;
  bool operator==(const TimeParams&) const = default;
};

/// Ideal gas (physics.eos = ideal_gas) and isothermal gas (isothermal).
struct GasParams {
  double gamma = 1.4;  ///< adiabatic index of P = (gamma-1) rho u (seed 000 eq. 3.3.23) [dimensionless]
  double cs = 1.0;     ///< isothermal sound speed, P = cs^2 rho [length/time]
  double K = 0.6366197723675814;  ///< polytropic constant of P = K rho^gamma [pressure/density^gamma] (2/pi: R = 1 for n = 1, G = M = 1)
  bool operator==(const GasParams&) const = default;
};

/// How DFSPH's pressure solves iterate (liquid.dfsph_solver; physics/dfsph_solver.h).
enum class DfsphSolverType {
  Jacobi,    ///< projected, relaxed Jacobi, as Bender & Koschier's Algorithms 2 and 3
  BiCGStab,  ///< BiCGStab on the particles under pressure (physics/dfsph_krylov.cpp): a pressure error smooth over the liquid too
};

/// Liquids: weakly compressible by the Tait/Cole EOS (physics.eos = tait; seed 001 eq. 3), or
/// incompressible by DFSPH's pressure solves (physics.eos = dfsph; Bender & Koschier 2017).
struct LiquidParams {
  double rho0 = 1000.0;  ///< reference density [kg/m^d]
  double c0 = 1414.2135623730951;  ///< sound speed at rho0 [m/s]; B = rho0 c0^2 / gamma
  double gamma = 7.0;    ///< Tait exponent (7 for water) [dimensionless]; not the gas gamma
  double p0 = 0.0;       ///< background pressure added to P [Pa]
  double p_min = -1e300; ///< floor of P [Pa]: a liquid cannot sustain much tension (cavitation near -1 atm)
  /// DFSPH: the constant-density solve iterates until the mean compression (rho* - rho0)/rho0 over the
  /// fluid is at most this [dimensionless] (Bender & Koschier 2017: 0.01%-0.1%)
  double dfsph_eta = 5e-4;
  /// DFSPH: the divergence solve iterates until the mean dt (Drho/Dt)/rho0 is at most this [dimensionless]
  double dfsph_eta_div = 1e-3;
  int dfsph_max_iter = 1000;  ///< DFSPH: cap on each solve's applications of the pressure operator (reaching it warns)
  DfsphSolverType dfsph_solver = DfsphSolverType::Jacobi;  ///< DFSPH: how the solves iterate
  bool operator==(const LiquidParams&) const = default;
};

/// Viscosity (physics.viscosity).
struct ViscParams {
  double alpha = 1.0;  ///< Monaghan Pi, linear term (seed 003 eq. 3.16; seed 001 eq. 41) [dimensionless]
  double beta = 2.0;   ///< Monaghan Pi, quadratic term [dimensionless]
  double eps = 0.01;   ///< eta^2 = eps h^2 regularises 1/r^2 in Pi and the Laplacian (seed 001 eq. 42) [dimensionless]
  double nu = 1e-6;    ///< kinematic viscosity of the Laplacian viscosity [length^2/time]
  // The switch (physics.visc_switch = cullen_dehnen): alpha per particle in [alpha_min, alpha_max]
  double alpha_min = 0.2;  ///< floor of alpha far from shocks (Sod: 0.1 gives L1(rho) 1.15x, 0.2 1.05x the constant alpha = 1) [dimensionless]
  double alpha_max = 1.0;  ///< alpha at a shock; Pi uses beta alpha_ab / alpha_max for its quadratic term [dimensionless]
  double decay = 0.1;      ///< alpha decays on tau = H / (decay c) behind a shock, H the kernel's support radius [dimensionless]
  bool operator==(const ViscParams&) const = default;
};

/// Artificial thermal conductivity (physics.conduction; Price 2008, JCP 227, 10040).
struct ConductionParams {
  double alpha_u = 1.0;  ///< strength [dimensionless]
  bool operator==(const ConductionParams&) const = default;
};

/// XSPH (physics.xsph; seed 001 eq. 45).
struct XsphParams {
  double eps = 0.5;  ///< v* = v + eps sum_b m_b (v_b - v_a)/rho_ab W_ab [dimensionless]
  bool operator==(const XsphParams&) const = default;
};

/// Uniform body force (physics.body_force = uniform).
struct BodyParams {
  double gx = 0.0, gy = -9.81, gz = 0.0;  ///< acceleration [length/time^2]
  double tau = 0.1;                        ///< damping time of physics.body_force = damping [time]
  bool operator==(const BodyParams&) const = default;
};

/// How the finite pointset method keeps its point set under control (seed 002 Note 3.2).
enum class PointControl {
  None,           ///< the points move with the flow (pure Lagrangian)
  Reinterpolate,  ///< after every step, u is interpolated by MLS back onto the initial points Gamma_0
  MergeSplit,     ///< points move with the flow; two closer than dx0/2 merge, a gap wider than 3 dx0/2 gets a midpoint
};

/// The finite pointset method (physics.fpm).
struct FpmParams {
  double alpha = 8.0;   ///< MLS weight exp(-alpha r^2 / h^2) (seed 002 eq. 9, Program 1) [dimensionless]
  double eps = 0.005;   ///< Burgers viscosity epsilon (seed 002 eq. 6a) [length^2/time]
  PointControl control = PointControl::Reinterpolate;
  bool operator==(const FpmParams&) const = default;
};

/// Self-gravity (physics.gravity = direct or tree).
struct GravityParams {
  double G = 1.0;        ///< gravitational constant [length^3/(mass time^2)]; 4 pi^2 in AU, Msun, yr
  double eps = 0.0;      ///< Plummer softening length [length]
  double theta = 0.5;    ///< Barnes-Hut opening angle [dimensionless]: 0 opens every cell (exact)
  double tol = 1e-3;     ///< the tree's relative guard [dimensionless]: a cell's dropped octupole <= tol |a_i|; 0 = off
  double fmm_theta = 0.8;  ///< FMM opening criterion [dimensionless]: cells interact when (r_A + r_B) < theta R
  double fmm_tol = 1e-3;   ///< FMM relative guard [dimensionless]: a cell pair's error estimate <= tol min|a|; 0 = off
  int fmm_order = 5;       ///< FMM expansion order [dimensionless]
  Softening softening = Softening::Plummer;
  bool operator==(const GravityParams&) const = default;
};

/// Wall particles (physics.walls).
struct WallParams {
  double D = 0.0;   ///< Lennard-Jones strength [length^2/time^2] (seed 001 eq. 60: D ~ 5 g H); 0 = the scene's
  double p1 = 4.0;  ///< repulsive exponent [dimensionless]
  double p2 = 2.0;  ///< attractive exponent, p1 > p2 [dimensionless]
  double r0 = 0.0;  ///< cut-off [length]; 0 = the scene's initial particle spacing
  double friction = 1.0;  ///< share of the viscosity between fluid and dummy walls: 1 no-slip, 0 free-slip
  bool operator==(const WallParams&) const = default;
};

/// Kernel and gradient corrections (physics.force = corrected or standard_corrected, and the MLS density
/// re-initialisation; seed 001 eqs. 17-37).
struct CorrectionParams {
  double min_rcond = 0.05;  ///< below this reciprocal condition number of the gradient-correction matrix,
                            ///< L = I is used instead (free surfaces, few neighbours) [dimensionless]
  bool operator==(const CorrectionParams&) const = default;
};

struct Params {
  Physics physics;           ///< the stage chosen for every slot
  KernelParams kernel;       ///< kernel.*
  DensityParams density;     ///< density.*
  SmoothingParams h;         ///< h.*
  TimeParams time;           ///< time.*
  GasParams gas;             ///< gas.*
  LiquidParams liquid;       ///< liquid.*
  ViscParams visc;           ///< visc.*
  ConductionParams conduction;  ///< conduction.*
  XsphParams xsph;           ///< xsph.*
  BodyParams body;           ///< body.*
  GravityParams gravity;     ///< gravity.*
  WallParams walls;          ///< walls.*
  CorrectionParams correction;  ///< correction.*
  FpmParams fpm;             ///< fpm.*
  bool operator==(const Params&) const = default;
};

const char* to_string(KernelType k);
const char* to_string(IntegratorType i);
bool parse(const std::string& s, KernelType& out);
bool parse(const std::string& s, IntegratorType& out);
const char* to_string(Softening s);
bool parse(const std::string& s, Softening& out);
const char* to_string(PointControl c);
const char* to_string(ViscSwitch s);
bool parse(const std::string& s, ViscSwitch& out);
const char* to_string(DfsphSolverType s);
bool parse(const std::string& s, DfsphSolverType& out);
bool parse(const std::string& s, PointControl& out);

}  // namespace sph
