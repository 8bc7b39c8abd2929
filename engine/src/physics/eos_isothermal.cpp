// Isothermal gas P = cs^2 rho (the n -> infinity polytrope of seed 003 eq. 3.72); its internal energy,
// int P/rho^2 drho, is cs^2 ln(rho) up to a constant: sum m cs^2 ln(rho) is reported.
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class EosIsothermal final : public Stage {
 public:
  std::string_view name() const override { return "EOS: isothermal"; }
  FieldSet needs() const override { return FieldSet{}.add(Field::Density); }
  FieldSet writes() const override { return FieldSet{}.add(Field::Pressure).add(Field::SoundSpeed); }
  FieldSet shares() const override { return writes(); }
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& rho = p[Field::Density];
    auto& P = p[Field::Pressure];
    auto& cs = p[Field::SoundSpeed];
    const double c0 = c.prm.gas.cs;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      P[i] = c0 * c0 * rho[i];
      cs[i] = c0;
    }
    return true;
  }
  double internal_energy(const StageContext& c) const override {
    const auto& m = c.p[Field::Mass];
    const auto& rho = c.p[Field::Density];
    const double c2 = c.prm.gas.cs * c.prm.gas.cs;
    double e = 0.0;
    for (std::size_t i = 0; i < c.p.fluid(); ++i) e += m[i] * c2 * std::log(rho[i]);
    return e;
  }
};

}  // namespace

std::unique_ptr<Stage> make_eos_isothermal() { return std::make_unique<EosIsothermal>(); }

}  // namespace sph
