// The internal energy equation du/dt (seed 000 eq. 3.3.19): its rate is summed in the standard force
// loop; the integrator advances u with it.
#include "core/stages.h"
#include "declared_stages.h"

namespace sph {

std::unique_ptr<Stage> make_energy_equation() {
  return std::make_unique<DeclaredStage>("energy equation", FieldSet{Field::Energy},
                                         std::vector<EvolvedPair>{{Field::Energy, Field::EnergyRate}});
}

}  // namespace sph
