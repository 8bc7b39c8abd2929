// Equations of state as pure functions of one particle (used by the EOS stages and the dummy walls).
#pragma once
#include <cmath>

#include "sph/params.h"

namespace sph::eos {

/// Tait/Cole (seed 001 eq. 3, written p = B[(rho/rho0)^gamma - 1] + p0 with B = p0_atm (k+1) of the
/// seed): B = rho0 c0^2 / gamma, so that dP/drho = c0^2 at rho0. Seed 001 §7.1 quotes k = 285.714 MN/m^2,
/// which is this B (a pressure), not the dimensionless k of eq. 3: with gamma = 7, rho0 = 1000 it gives
/// c0 = sqrt(gamma B/rho0) = 1414.2 m/s.
inline double tait_B(const LiquidParams& l) { return l.rho0 * l.c0 * l.c0 / l.gamma; }
inline double tait_pressure(double rho, const LiquidParams& l) {
  return tait_B(l) * (std::pow(rho / l.rho0, l.gamma) - 1.0) + l.p0;
}
/// c = sqrt(dP/drho) = c0 (rho/rho0)^((gamma-1)/2).
inline double tait_sound_speed(double rho, const LiquidParams& l) {
  return l.c0 * std::pow(rho / l.rho0, 0.5 * (l.gamma - 1.0));
}
/// The density at pressure P (the inverse of tait_pressure); P below p0 - B has none (returns 0).
inline double tait_density(double P, const LiquidParams& l) {
  const double x = (P - l.p0) / tait_B(l) + 1.0;
  return x > 0.0 ? l.rho0 * std::pow(x, 1.0 / l.gamma) : 0.0;
}
/// Specific elastic energy e(rho) = int_rho0^rho P/rho'^2 drho' (0 at rho0): with it E_kin + sum m e is
/// conserved by the barotropic equations [energy/mass].
inline double tait_energy(double rho, const LiquidParams& l) {
  const double B = tait_B(l), g = l.gamma;
  return B / ((g - 1.0) * std::pow(l.rho0, g)) * (std::pow(rho, g - 1.0) - std::pow(l.rho0, g - 1.0)) +
         (B - l.p0) * (1.0 / rho - 1.0 / l.rho0);
}

/// Ideal gas (seed 000 eq. 3.3.23): P = (gamma - 1) rho u, c = sqrt(gamma P / rho).
inline double ideal_gas_pressure(double rho, double u, double gamma) { return (gamma - 1.0) * rho * u; }

}  // namespace sph::eos
