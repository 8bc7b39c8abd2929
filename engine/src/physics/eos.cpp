// Ideal-gas equation of state (seed 000 eq. 3.3.23; seed 003 eqs. 3.52–3.53).
#include <cmath>
#include "core/parallel.h"

#include "sph/hydro.h"

namespace sph {

void ideal_gas_eos(const Params& prm, Particles& p) {
  const std::size_t n = p.size();
  const auto& rho = p[Field::Density];
  const auto& u = p[Field::Energy];
  auto& P = p[Field::Pressure];
  auto& c = p[Field::SoundSpeed];
  const double g = prm.gamma;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    P[i] = (g - 1.0) * rho[i] * u[i];
    c[i] = std::sqrt(g * P[i] / rho[i]);
  }
}

}  // namespace sph
