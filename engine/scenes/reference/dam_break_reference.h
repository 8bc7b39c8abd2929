// The dam break's reference: the surge front of the particles against the measured fronts.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

/// a: column width [m]; dx: particle spacing [m] (the front is the foremost fluid centre + dx/2);
/// g: gravity [m/s^2].
std::unique_ptr<Reference> make_dam_break_reference(double a, double dx, double g);

}  // namespace sph::scenes
