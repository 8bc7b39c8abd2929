// The polytrope's reference: the Lane-Emden density profile and the virial ratio (seed 003 eq. 3.79).
#pragma once
#include <memory>

#include "sph/params.h"
#include "sph/reference.h"

namespace sph::scenes {

/// Density in 8 shells inside 0.8 R (about the centre of mass) against the Lane-Emden density averaged
/// over the same particles, and 3 sum m P/rho / |W| with W = 1/2 sum m phi (1 in equilibrium).
std::unique_ptr<Reference> make_polytrope_reference(const Params& prm, double M);

}  // namespace sph::scenes
