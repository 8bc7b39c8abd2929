// The colliding polytropes' reference (seed 003 §3.4.4): the distance between the two stars' centres of
// mass against that of two point masses from the same start (the shell theorem makes them equal until
// the stars touch and deform), the peak density against the stars' Lane-Emden central density, and the
// drift of the total centre of mass.
#pragma once
#include <cstddef>
#include <memory>

#include "sph/params.h"
#include "sph/reference.h"
#include "sph/vec.h"

namespace sph::scenes {

/// Two stars of mass M each, the first n particle ids the first star, centres initially `r0` apart
/// (second minus first) with relative velocity `v0`.
std::unique_ptr<Reference> make_collision_reference(const Params& prm, std::size_t n, double M, Vec3 r0, Vec3 v0);

}  // namespace sph::scenes
