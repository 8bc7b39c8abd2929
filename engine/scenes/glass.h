// Glass starts: a relaxed, disordered particle distribution without a lattice's preferred directions
// and with far less density noise than random points (White 1994, "Les Houches" lectures, who made
// cosmological glasses with reversed gravity; here SPH pressure with damping does it). n random points
// in the periodic unit box are run with the isothermal SPH equations and the damping a = -v/tau until
// the pressure forces balance; the result is memoised in-process per (dim, n, seed), so a scene reset
// or a second scene with the same glass reuses it.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "sph/vec.h"

namespace sph::scenes {

/// How the glass is relaxed (everything the positions depend on besides dim, n and seed).
struct GlassRecipe {
  double t_relax = 60.0;  ///< relaxation time in units of the mean spacing / sound speed [dx/c]
  double tau = 2.0;       ///< damping time of a = -v/tau [dx/c]
};

/// n positions in [0,1)^dim (unused axes 0), periodic: the box tiles space without a seam. Deterministic
/// (the same on every run and thread count). Thread safe; the same glass is built once.
std::shared_ptr<const std::vector<Vec3>> glass(int dim, std::size_t n, std::uint64_t seed);

/// The same glass built afresh (no memo): what glass() stores. For tests of its determinism.
std::vector<Vec3> make_glass(int dim, std::size_t n, std::uint64_t seed);

/// The same, with the random start before any relaxation (for comparison in tests and reports).
std::vector<Vec3> glass_random_start(int dim, std::size_t n, std::uint64_t seed);

/// Fills [lo, hi) with glass of mean spacing near `spacing`: tiles of at most max_tile particles (a
/// glass of its own count, generated once), as many per axis as the box needs, each tile scaled to its
/// share of the box (tiles are as near cubic as the box allows; a periodic glass tiles without seams).
std::vector<Vec3> glass_fill(int dim, const Vec3& lo, const Vec3& hi, double spacing, std::uint64_t seed,
                             std::size_t max_tile = 16384);

}  // namespace sph::scenes
