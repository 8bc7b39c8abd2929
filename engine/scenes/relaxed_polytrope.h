// A relaxed polytropic star to build scenes from (seed 003 §3.4.3-3.4.4): the polytrope scene's star
// (Lane-Emden placement, M = 1) run with its damping a = -v/tau for a given time by a World of its own,
// then taken at rest about its centre of mass. Memoised per parameter set: a scene reset reuses it.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "sph/params.h"
#include "sph/vec.h"

namespace sph::scenes {

/// The star as relaxation left it, in particle-id order.
struct RelaxedStar {
  std::vector<Vec3> x;            ///< position about the centre of mass [length]
  std::vector<double> m, h, rho;  ///< mass [mass], smoothing length [length], SPH density [mass/length^3]
};

/// n particles, placement seed `seed`, relaxed for t_relax [time] with the polytrope scene's physics
/// (its damping time body.tau = 0.1 included) and the star-defining parameters of prm (gas.gamma,
/// gas.K, gravity.G and .theta, kernel, h solve). Thread safe.
std::shared_ptr<const RelaxedStar> relaxed_polytrope(const Params& prm, std::size_t n, std::uint64_t seed,
                                                     double t_relax);

}  // namespace sph::scenes
