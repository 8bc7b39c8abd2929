// The smooth Kelvin-Helmholtz set-up of McNally, Lyra & Passy (2012, ApJS 201, 18: their initial conditions) on the
// periodic unit square: a dense band rho2 = 2 moving at U2 = -0.5 for 0.25 < y < 0.75 between light gas
// rho1 = 1 at U1 = +0.5, joined by exponential ramps of width L (0.025) that are C1 at y = 0.25, 0.75:
//   y < 1/4:       rho = rho1 - rho_m e^((y-1/4)/L),   U = U1 - U_m e^((y-1/4)/L)
//   1/4 <= y < 1/2: rho = rho2 + rho_m e^((1/4-y)/L),   U = U2 + U_m e^((1/4-y)/L)
// and mirrored about y = 1/2, with rho_m = (rho1 - rho2)/2, U_m = (U1 - U2)/2; P = 5/2, gamma = 5/3 and the
// seed v_y = 0.01 sin(4 pi x).
#pragma once
#include <cmath>

namespace sph::scenes::kh {

inline constexpr double kRho1 = 1.0, kRho2 = 2.0, kU1 = 0.5, kU2 = -0.5, kPressure = 2.5;
inline constexpr double kRhoM = 0.5 * (kRho1 - kRho2), kUM = 0.5 * (kU1 - kU2);

/// exp(-(distance from the nearer interface)/L) and whether y is inside the dense band, y in [0, 1).
inline double ramp(double y, double L, bool& dense) {
  const double d = y < 0.5 ? y - 0.25 : 0.75 - y;  // > 0 inside the band
  dense = d >= 0.0;
  return std::exp(-std::abs(d) / L);
}

inline double density(double y, double L) {
  bool dense;
  const double e = ramp(y, L, dense);
  return dense ? kRho2 + kRhoM * e : kRho1 - kRhoM * e;
}

inline double velocity(double y, double L) {
  bool dense;
  const double e = ramp(y, L, dense);
  return dense ? kU2 + kUM * e : kU1 - kUM * e;
}

/// dU/dy across the lower interface (y in [0, 1/2)); the upper one is its mirror image.
inline double velocity_slope_lower(double y, double L) {
  bool dense;
  const double e = ramp(y, L, dense);
  return -kUM * e / L;
}

}  // namespace sph::scenes::kh
