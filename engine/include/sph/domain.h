// The simulation box and its boundaries. Periodic boundaries (seed 000 §4.1.1) and reflecting walls with
// fictitious mirror particles (seed 000 §4.2.1) are both realised by ghost particles appended after the
// real ones, so the neighbour search and the physics loops never special-case a boundary.
#pragma once
#include <stdexcept>
#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/particles.h"

namespace sph {

enum class Boundary { Open, Periodic, Wall };

struct Domain {
  std::array<double, 3> lo{0, 0, 0};  ///< lower corner [length]
  std::array<double, 3> hi{1, 1, 1};  ///< upper corner [length]
  std::array<Boundary, 3> bc{Boundary::Open, Boundary::Open, Boundary::Open};  ///< per axis, both sides
  double length(int k) const { return hi[k] - lo[k]; }
};

/// More ghosts than kMaxGhostsPerParticle per real particle (plus a few hundred for tiny sets): the margin,
/// i.e. h, has outgrown a periodic box many times over, which only a blown-up run reaches.
struct GhostOverflow : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline constexpr std::size_t kMaxGhostsPerParticle = 64;

/// Rebuild the ghost particles for every real particle within `margin` of a periodic or wall boundary
/// (corners included). Sets positions, ids, kinds, ghost_src and ghost_flip; the state is copied by
/// copy_ghost_velocity and copy_ghost_field. Deterministic: ghosts are appended axis by axis in particle order.
/// Throws GhostOverflow (before allocating them) when the ghosts would exceed the bound above.
void make_ghosts(const Domain& d, double margin, Particles& p);

/// Moves every ghost with its source (the transform make_ghosts recorded): the ghosts of lists kept
/// between evaluations. Gives the positions make_ghosts would give for the same sources, bit for bit.
void update_ghost_positions(Particles& p);

/// Copy velocity (mirrored across walls) and fields from each ghost's source. Vector and tensor
/// components change sign as their FieldInfo::flip_axes say (a mirror reverses the normal component).
void copy_ghost_velocity(Particles& p);
void copy_ghost_field(Particles& p, Field f);
void copy_ghost_fields(Particles& p, FieldSet fields);

/// What apply_boundaries had to do at the walls: particles that had crossed one (reflected back), and
/// particles so far beyond that the reflection leaves them outside the domain (they escaped).
struct WallCrossings {
  std::size_t reflected = 0, escaped = 0;
  std::size_t first_reflected = SIZE_MAX, first_escaped = SIZE_MAX;  ///< lowest storage indices
};

/// Wrap real particles into periodic axes and reflect those that crossed a wall (specular bounce).
WallCrossings apply_boundaries(const Domain& d, Particles& p);

}  // namespace sph
