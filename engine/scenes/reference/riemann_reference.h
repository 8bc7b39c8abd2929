// The exact Riemann solution as the reference of a 1D shock tube: L1 norms of rho, v, P, u over the
// particles between the walls, and the exact profiles for the plots.
#pragma once
#include <memory>

#include "sph/reference.h"
#include "sph/riemann.h"

namespace sph::scenes {

/// x in [lo, hi] is compared (the tube between its walls).
std::unique_ptr<Reference> make_riemann_reference(GasState left, GasState right, double gamma, double x0, double lo,
                                                  double hi);

}  // namespace sph::scenes
