// The Noh implosion's reference: the post-shock density away from the centre and the shock, the shock
// radius, and the wall heating at the centre, against Noh's exact solution.
#pragma once
#include <memory>

#include "reference/noh_solution.h"
#include "sph/reference.h"

namespace sph::scenes {

struct NohSetup {
  Noh noh;
  double margin = 0.01;  ///< band behind the shock left out of the post-shock average (a few h) [length]
  double dr = 0.005;     ///< shell width of the measured profile [length]
  double r_max = 1.0;    ///< shells out to this radius; the gas's initial outer radius [length]
};

/// Regions at time t, with R = t/3 (gamma = 5/3): wall heating r < R/3; post-shock R/3 < r < R - margin.
std::unique_ptr<Reference> make_noh_reference(const NohSetup& s);

}  // namespace sph::scenes
