// The force stage's sums for one particle, split into their terms (pressure, artificial or physical
// viscosity, conduction) and into their pairs, with the same per-pair maths as the force loops
// (physics/pair_terms.h, corrected_kernel.h) over the same neighbour lists and filters. The terms add
// up to what the stage itself computed for that particle (tests/engine/force_terms_test.cpp).
#pragma once
#include <string>
#include <vector>

#include "core/stage.h"
#include "sph/inspect.h"

namespace sph {

/// Appends the terms of particle i's force stage to *terms and its interacting neighbours to *nb;
/// returns the formulation's name ("standard", ...), or "" when the scene has no force stage.
std::string force_terms(const StageContext& c, std::size_t i, std::vector<InspectTerm>* terms,
                        std::vector<InspectNeighbour>* nb);

}  // namespace sph
