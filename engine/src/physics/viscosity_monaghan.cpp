// Monaghan artificial viscosity Pi_ab (seed 003 eq. 3.16; seed 001 eqs. 41-43): evaluated per pair in
// the force loops (pair_terms.h); it needs the sound speeds, and its Courant limit is folded into the
// pair signal speed.
#include "core/stages.h"
#include "declared_stages.h"

namespace sph {

std::unique_ptr<Stage> make_viscosity_monaghan() {
  return std::make_unique<DeclaredStage>("viscosity: Monaghan Pi", FieldSet{Field::SoundSpeed});
}

}  // namespace sph
