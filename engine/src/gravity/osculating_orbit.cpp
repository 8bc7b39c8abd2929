// The osculating two-body orbit (two-body problem: energy, angular momentum, eccentricity vector
// magnitude, pericentre from the semi-latus rectum p = L^2/mu as q = p/(1 + e), exact also for e >= 1).
#include "gravity/osculating_orbit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph::gravity {

OsculatingOrbit osculating_orbit(const Vec3& dx, const Vec3& dv, double mu) {
  OsculatingOrbit o;
  o.energy = 0.5 * dv.norm2() - mu / dx.norm();
  o.L = dx.cross(dv).norm();
  o.e = std::sqrt(std::max(0.0, 1.0 + 2.0 * o.energy * o.L * o.L / (mu * mu)));
  o.q = o.L * o.L / (mu * (1.0 + o.e));
  o.t_q = std::sqrt(o.q * o.q * o.q / mu);
  return o;
}

double leapfrog_energy_error(const OsculatingOrbit& o, double dt) {
  if (!(o.t_q > 0.0)) return std::numeric_limits<double>::infinity();
  const double s = dt / o.t_q;
  return kLeapfrogEnergyC * o.e * s * s;
}

double leapfrog_dt_for(const OsculatingOrbit& o, double err) {
  if (!(o.e > 0.0)) return std::numeric_limits<double>::infinity();
  return o.t_q * std::sqrt(err / (kLeapfrogEnergyC * o.e));
}

}  // namespace sph::gravity
