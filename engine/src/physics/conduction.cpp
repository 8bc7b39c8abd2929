// Artificial thermal conductivity (Price 2008, JCP 227, 10040): a term of the energy equation evaluated
// in the standard force loop; it reads the neighbours' u and P.
#include "core/stages.h"
#include "declared_stages.h"

namespace sph {

std::unique_ptr<Stage> make_conduction() {
  return std::make_unique<DeclaredStage>("conduction: Price 2008", FieldSet{Field::Energy, Field::Pressure});
}

}  // namespace sph
