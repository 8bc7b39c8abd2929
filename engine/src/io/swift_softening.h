// SWIFT's gravity softening for a scene softened with Plummer's law. SWIFT spreads each mass with a
// Wendland C2 kernel of support H = 3 eps_S (src/kernel_gravity.h), Newtonian beyond H and "Plummer
// equivalent" only at r = 0 (phi(0) = -G m / eps_S); Plummer's law softens at every distance. No eps_S
// gives the same force at every r, so the export writes the eps_S whose potential energy of the state
// written equals this code's (the t = 0 energies then agree): for Evrard's eps = 0.05, eps_S = 0.106.
#pragma once
#include "sph/particles.h"

namespace sph {

/// Largest particle count whose match is computed (pair sums, O(N^2) per trial eps_S).
constexpr std::size_t kSoftMatchMaxN = 8192;

/// The eps_S at which the pair sum of SWIFT's softened potential over particles 0..n-1 equals Plummer's
/// with eps [length]; 0 when n > kSoftMatchMaxN.
double swift_softening_matching_plummer(const Particles& p, std::size_t n, double eps);

}  // namespace sph
