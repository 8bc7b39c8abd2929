// The elliptical drop's reference: semi-axes measured from the particles against the ODE of drop_ode.h.
#pragma once
#include <memory>

#include "sph/reference.h"

namespace sph::scenes {

std::unique_ptr<Reference> make_drop_reference(double A0);

}  // namespace sph::scenes
