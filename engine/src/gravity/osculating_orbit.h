// The osculating two-body (Kepler) orbit of a pair of point masses, from their relative position and
// velocity and mu = G (m1 + m2): specific energy, specific angular momentum, eccentricity, pericentre
// q, and the time scale of the pericentre passage t_q = sqrt(q^3 / mu) that a fixed timestep has to
// resolve. The leapfrog's energy error over such an orbit peaks at about C e (dt / t_q)^2.
#pragma once
#include "sph/vec.h"

namespace sph::gravity {

struct OsculatingOrbit {
  double energy = 0.0;  ///< specific orbital energy v^2/2 - mu/r [length^2/time^2]; < 0: bound
  double L = 0.0;       ///< specific angular momentum |r x v| [length^2/time]
  double e = 0.0;       ///< eccentricity sqrt(1 + 2 energy L^2 / mu^2)
  double q = 0.0;       ///< pericentre distance L^2 / (mu (1 + e)) [length]; 0 for a radial orbit
  double t_q = 0.0;     ///< passage time scale sqrt(q^3 / mu) at the pericentre [time]
  bool bound() const { return energy < 0.0; }
};

/// The orbit of relative position dx and velocity dv about mu = G (m1 + m2) > 0.
OsculatingOrbit osculating_orbit(const Vec3& dx, const Vec3& dv, double mu);

/// C of the leapfrog's largest relative energy error C e (dt / t_q)^2 over an orbit: measured 0.6 to 1.3
/// (kepler started at aphelion, 100 orbits at dt = 0.002 yr, e = 0.017 ... 0.95); 2 is conservative.
inline constexpr double kLeapfrogEnergyC = 2.0;

/// The leapfrog's expected largest |dE/E| of the orbit at a fixed timestep dt (infinite when t_q = 0).
double leapfrog_energy_error(const OsculatingOrbit& o, double dt);
/// The largest fixed timestep whose expected |dE/E| (leapfrog_energy_error) stays within `err`.
double leapfrog_dt_for(const OsculatingOrbit& o, double err);

}  // namespace sph::gravity
