// Ideal-gas equation of state P = (gamma-1) rho u, c = sqrt(gamma P/rho) (seed 000 eq. 3.3.23; seed 003
// eqs. 3.52-3.53). Its internal energy is sum m u.
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class EosIdealGas final : public Stage {
 public:
  bool reads_every_list() const override { return false; }  // reads no lists
  EosIdealGas()
      : Stage({.name = "EOS: ideal gas",
               .needs = {Field::Density, Field::Energy},
               .writes = {Field::Pressure, Field::SoundSpeed},
               .shares = {Field::Pressure, Field::SoundSpeed, Field::Energy}}) {}
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& rho = p[Field::Density];
    const auto& u = p[Field::Energy];
    auto& P = p[Field::Pressure];
    auto& cs = p[Field::SoundSpeed];
    const double g = c.prm.gas.gamma;
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      P[i] = (g - 1.0) * rho[i] * u[i];
      cs[i] = std::sqrt(g * P[i] / rho[i]);
    }
    return true;
  }
  double internal_energy(const StageContext& c) const override {
    const auto& m = c.p[Field::Mass];
    const auto& u = c.p[Field::Energy];
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < c.p.fluid(); ++i) e += m[i] * u[i];
    return e;
  }
};

}  // namespace

std::unique_ptr<Stage> make_eos_ideal_gas() { return std::make_unique<EosIdealGas>(); }

}  // namespace sph
