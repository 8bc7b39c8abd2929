// The viscosity term of a scene's physics as a type, chosen once per pair loop: fn(tag) is called with
// a Tag<T> of the term type T (visc_*.h). A new viscosity option is its visc_NAME.h, its line here and
// the enum/option line of sph/physics.h (README "Add a stage option").
#pragma once
#include "sph/physics.h"
#include "visc_laplacian.h"
#include "visc_monaghan.h"
#include "visc_monaghan_switched.h"
#include "visc_none.h"

namespace sph::terms {

template <class T>
struct Tag {
  using type = T;
};

template <class Fn>
decltype(auto) with_viscosity(const Physics& ph, Fn&& fn) {
  switch (ph.viscosity) {
    case ViscType::Monaghan:
      if (ph.visc_switch != ViscSwitch::None) return fn(Tag<ViscMonaghanSwitched>{});
      return fn(Tag<ViscMonaghan>{});
    case ViscType::Laplacian: return fn(Tag<ViscLaplacian>{});
    case ViscType::None: break;
  }
  return fn(Tag<ViscNone>{});
}

}  // namespace sph::terms
