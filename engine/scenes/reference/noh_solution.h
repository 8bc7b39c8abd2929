// Noh's implosion (Noh 1987, J. Comput. Phys. 72, 78, §§5-6): cold gas (P = 0) of density rho0 streams
// towards the origin at speed v0 in d = 1, 2, 3 (planar, cylindrical, spherical). A shock stands up at
// the origin and moves out at U = (gamma-1) v0 / 2; behind it the gas is at rest with
// rho2 = rho0 ((gamma+1)/(gamma-1))^d, u2 = v0^2/2 and P2 = (gamma-1) rho2 u2; ahead of it the converging
// flow piles up as rho = rho0 (1 + v0 t / r)^(d-1). (gamma = 5/3, d = 2: rho2 = 16, P2 = 16/3, R = t/3.)
#pragma once

namespace sph::scenes {

struct NohState {
  double rho = 0, v = 0, P = 0, u = 0;  ///< density, radial velocity (negative: inwards), pressure, specific u
};

struct Noh {
  int dim = 2;
  double gamma = 5.0 / 3.0;
  double rho0 = 1.0;  ///< initial density [mass/length^d]
  double v0 = 1.0;    ///< inflow speed [length/time]

  double shock_speed() const { return 0.5 * (gamma - 1.0) * v0; }
  double shock_radius(double t) const { return shock_speed() * t; }
  double post_shock_density() const;
  /// The exact flow at distance r > 0 and time t >= 0.
  NohState state(double r, double t) const;
};

}  // namespace sph::scenes
