// References of the N-body scenes (seed 003 ch. 2): energy and angular momentum of point masses
// against their initial values (seed 003 eqs. 2.8, 2.13, 2.24), the closed-form radial fall (eq. 2.17)
// and the Kepler orbit (position against time from Kepler's equation).
#pragma once
#include <memory>
#include <vector>

#include "nbody_common.h"
#include "sph/reference.h"

namespace sph::scenes {

/// E = sum 1/2 m v^2 - sum_{i<j} G m_i m_j / sqrt(r_ij^2 + eps^2) and L_z of point masses.
struct Invariants {
  double E = 0.0, Lz = 0.0;
};
Invariants invariants(const std::vector<Body>& b, double G, double eps);
Invariants invariants(const Particles& p, double G, double eps);

/// |E/E0 - 1| and |L/L0 - 1| (relative to |L0|) of the particles.
std::unique_ptr<Reference> make_conservation_reference(const std::vector<Body>& initial, double G, double eps);
/// Separation of bodies 0 and 1 against seed 003 eq. 2.17 (two bodies released at rest at distance r0).
std::unique_ptr<Reference> make_fall_reference(const std::vector<Body>& initial, double G);
/// Relative position of bodies 1 and 0 against the Kepler orbit of their initial state.
std::unique_ptr<Reference> make_kepler_reference(const std::vector<Body>& initial, double G);

/// The closed-form fall, seed 003 eq. 2.17: separation at time t of two bodies released at rest at r0
/// with mu = G (m1 + m2). The seed prints -arccos(sqrt x) - sin(2 arccos(sqrt x))/2 = sqrt(2 G m_S) t;
/// the left side must be positive (dx/dt < 0 on the fall): theta + sin(2 theta)/2 = sqrt(2 mu / r0^3) t,
/// x = r/r0 = cos^2 theta. The seed takes mu = G m_S (the Sun fixed); here both bodies move.
double fall_separation(double r0, double mu, double t);
/// Time at which the fall reaches r = 0: pi/2 sqrt(r0^3 / (2 mu)).
double fall_time(double r0, double mu);

}  // namespace sph::scenes
