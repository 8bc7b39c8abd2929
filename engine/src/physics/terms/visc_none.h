// No viscosity: the pair loops add no viscous term (physics.viscosity = none). A viscosity term type
// tells a pair loop which of its parts it has: kPi (a pair pressure Pi_ab added to the pressure bracket)
// and kLaplacian (a term k_ab v_ab of its own), and scales the pair signal speed (pair_terms.h).
#pragma once
#include <string_view>

#include "core/stage.h"

namespace sph::terms {

struct ViscNone {
  static constexpr bool kPi = false;
  static constexpr bool kLaplacian = false;
  static constexpr std::string_view kName = "none";
  double alpha_scale = 1.0, beta_scale = 1.0;  ///< factors of the pair signal speed [dimensionless]
  explicit ViscNone(const StageContext&) {}
};

}  // namespace sph::terms
