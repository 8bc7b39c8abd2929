// Linear Kelvin-Helmholtz growth of a smooth, compressible shear layer: the parallel flow U(y) x-hat with
// density rho(y) at uniform pressure P (no gravity), perturbed by f(y) exp(i k x + s t). The linearised
// Euler equations (adiabatic) reduce, with Omega = s + i k U, to the first-order system
//   dp/dy = -rho Omega v,    dv/dy = -(Omega/(gamma P) + k^2/(rho Omega)) p + i k U' v / Omega
// (e.g. Blumen, Drazin & Billings 1975, J. Fluid Mech. 71, 305, for the compressible shear layer), with
// p ~ exp(-+lambda y), lambda^2 = k^2 + rho Omega^2/(gamma P), outside the layer. The eigenvalue s is
// found by shooting (RK4) from both uniform states towards the layer's middle, each solution in the
// direction in which it grows, and a secant iteration on the mismatch of v/p there, from the vortex
// sheet's rate as first guess.
#pragma once
#include <complex>
#include <functional>

namespace sph::scenes {

/// One shear layer: profiles valid on [y_lo, y_hi], uniform (to round-off of the ODE) at both ends.
struct ShearLayer {
  std::function<double(double)> rho;   ///< density rho(y)
  std::function<double(double)> U;     ///< velocity U(y) along x
  std::function<double(double)> dUdy;  ///< its derivative
  double y_lo = 0.0, y_hi = 1.0;       ///< where the layer's solution is matched to the uniform states
  double P = 1.0;                      ///< uniform pressure
  double gamma = 5.0 / 3.0;            ///< adiabatic index
};

struct KhMode {
  std::complex<double> s;  ///< eigenvalue: Re s the growth rate [1/time], -Im s / k the phase speed
  int iterations = 0;      ///< secant iterations taken
  bool converged = false;
};

/// The fastest-growing mode of wavenumber k [1/length]; `steps` RK4 steps across [y_lo, y_hi].
KhMode kh_linear_mode(const ShearLayer& layer, double k, int steps = 4000);

/// The incompressible vortex sheet's rate sigma = k |dU| sqrt(rho1 rho2) / (rho1 + rho2)
/// (Chandrasekhar 1961, Hydrodynamic and Hydromagnetic Stability, §101) [1/time].
double kh_vortex_sheet_rate(double k, double rho1, double rho2, double dU);

}  // namespace sph::scenes
