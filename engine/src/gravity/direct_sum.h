// Direct summation of self-gravity (seed 003 eq. 2.3, softened eq. 2.43): for every particle, a gather
// over all others in storage order, so the result is bitwise the same for any thread count. O(N^2).
#pragma once
#include "gravity/softening.h"
#include "gravity/sources.h"

namespace sph::gravity {

void direct_sum(const Sources& s, const PairLaw& law, double G, Result& out);

}  // namespace sph::gravity
