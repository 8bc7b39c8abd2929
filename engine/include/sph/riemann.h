// Exact solution of the Riemann problem for the 1D Euler equations with an ideal (gamma-law) gas.
// Reference for shock-tube scenes: seed 003 eqs. 3.20-3.51 (Castellanos 2010) and Toro,
// "Riemann Solvers and Numerical Methods for Fluid Dynamics", ch. 4.
// Units are whatever the caller uses consistently (code units); nothing here is dimensional.
#pragma once

namespace sph {

struct GasState { double rho, v, p; };               // density, velocity, pressure
struct RiemannStar { double p, v; int iterations; }; // star-region pressure and velocity
struct WaveSpan { double s_min, s_max; };            // speeds of the fan's left and right edges

/// Exact solution of the Riemann problem L | R at x0 (seed 003 eqs. 3.20-3.51; Toro ch. 4).
/// Immutable after construction: every const member is thread-safe and deterministic.
class RiemannSolver {
 public:
  /// throws std::invalid_argument on non-positive rho/p, gamma<=1 or a vacuum-generating state.
  RiemannSolver(GasState left, GasState right, double gamma, double x0 = 0.0);
  RiemannStar star() const;
  /// Speeds of the outermost edges of the waves (shock speed or rarefaction head), Toro §4.5.
  WaveSpan span() const;
  /// State at position x and time t >= 0 (t == 0 gives the initial discontinuity).
  GasState sample(double x, double t) const;
  /// specific internal energy p/((gamma-1) rho) at (x,t)
  double internal_energy(double x, double t) const;
  double gamma() const;

 private:
  GasState sample_speed(double s) const;  // self-similar solution at s = (x - x0)/t

  GasState left_, right_;
  double gamma_, x0_;
  double c_left_, c_right_;               // sound speeds of the initial states
  RiemannStar star_;                      // p*, u* and Newton iteration count
  double rho_star_left_, rho_star_right_; // densities either side of the contact
};

}  // namespace sph
