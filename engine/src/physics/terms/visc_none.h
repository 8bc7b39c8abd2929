// No viscosity: the pair loops add no viscous term (physics.viscosity = none); the parts a viscosity
// term type has are visc_parts.h's.
#pragma once
#include <string_view>

#include "core/stage.h"
#include "visc_parts.h"

namespace sph::terms {

struct ViscNone : ViscParts<false, false> {
  static constexpr std::string_view kName = "none";
  explicit ViscNone(const StageContext&) {}
};

}  // namespace sph::terms
