// Wall forces as pure functions (used by the wall stages and their tests).
#pragma once
#include <cmath>

namespace sph::walls {

/// Lennard-Jones wall force per unit mass, radial factor (seed 001 eq. 60; Monaghan 1994):
/// f(r) = D [(r0/r)^p1 - (r0/r)^p2] r_vec / r^2 for r <= r0, 0 beyond. Returns the factor of r_vec
/// (positive: repulsive for p1 > p2, since r0/r >= 1 inside the cut-off) [1/time^2].
inline double lennard_jones_factor(double r, double D, double r0, double p1, double p2) {
  if (!(r > 0.0) || r > r0) return 0.0;
  const double q = r0 / r;
  return D * (std::pow(q, p1) - std::pow(q, p2)) / (r * r);
}

/// Its potential per unit mass, 0 at r0 and beyond: phi(r) = D [(q^p1 - 1)/p1 - (q^p2 - 1)/p2],
/// q = r0/r, so that f = -dphi/dr r_hat [length^2/time^2].
inline double lennard_jones_potential(double r, double D, double r0, double p1, double p2) {
  if (!(r > 0.0) || r > r0) return 0.0;
  const double q = r0 / r;
  const double t2 = p2 > 0.0 ? (std::pow(q, p2) - 1.0) / p2 : std::log(q);
  return D * ((std::pow(q, p1) - 1.0) / p1 - t2);
}

}  // namespace sph::walls
