// Run parameters: a plain value struct with defaults and units. The engine steps on a const Params&;
// the GUI edits its own copy and hands it over whole. Every field is declared once in param_table.cpp,
// which drives the JSON key, the --set override and (later) the GUI widget.
#pragma once
#include <string>

namespace sph {

/// Smoothing kernels of seed 000 eqs. 3.2.6–3.2.9 plus Wendland C2/C4 (Wendland 1995; Dehnen & Aly 2012).
enum class KernelType { M4, M5, M6, Gaussian, WendlandC2, WendlandC4 };
/// Time integrators: explicit Euler, RK4 (seed 000 App. A), leapfrog kick-drift-kick,
/// and the modified-Euler predictor-corrector of seed 001 eqs. 56–59.
enum class IntegratorType { Euler, RK4, Leapfrog, PredictorCorrector };
/// Smoothing length: h = eta (m/rho)^(1/d) solved with rho (seed 000 eq. 3.2.21), or held fixed.
enum class HMode { Variable, Fixed };

struct Params {
  // --- kernel and smoothing length -------------------------------------------------------------
  KernelType kernel = KernelType::M4;  ///< kernel family (live: takes effect at the next step)
  double eta = 0.0;                    ///< h = eta (m/rho)^(1/d); 0 = the kernel's default (dimensionless)
  HMode h_mode = HMode::Variable;      ///< variable (grad-h, Omega terms) or fixed h
  double h_tol = 1e-10;                ///< Newton-Raphson relative tolerance on h (dimensionless)
  int h_max_iter = 30;                 ///< Newton-Raphson iteration cap before bisection fallback

  // --- gas ---------------------------------------------------------------------------------------
  double gamma = 1.4;  ///< adiabatic index of P = (gamma-1) rho u (seed 000 eq. 3.3.23)

  // --- dissipation -------------------------------------------------------------------------------
  double alpha = 1.0;     ///< Monaghan viscosity linear term (seed 003 eq. 3.16)
  double beta = 2.0;      ///< Monaghan viscosity quadratic term (seed 003 eq. 3.16)
  double visc_eps = 0.01; ///< eta^2 = visc_eps h^2 in the viscosity denominator (seed 003 eq. 3.16)
  double alpha_u = 0.0;   ///< artificial thermal conductivity (Price 2008, JCP 227, 10040); 0 = off

  // --- time integration --------------------------------------------------------------------------
  IntegratorType integrator = IntegratorType::Leapfrog;
  double dt = 0.0;       ///< fixed timestep (time units); 0 = adaptive with cfl
  double cfl = 0.3;      ///< Courant factor for the adaptive timestep: dt = cfl h / v_sig (and force limit)
  double t_end = 0.2;    ///< end time of a run (time units)
  double dt_out = 0.05;  ///< interval between particle outputs (time units)
};

const char* to_string(KernelType k);
const char* to_string(IntegratorType i);
const char* to_string(HMode m);
bool parse(const std::string& s, KernelType& out);
bool parse(const std::string& s, IntegratorType& out);
bool parse(const std::string& s, HMode& out);

}  // namespace sph
