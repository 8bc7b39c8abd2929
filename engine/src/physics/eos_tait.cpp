// Tait/Cole equation of state for a weakly compressible liquid (seed 001 eq. 3; see sph/eos.h), with
// the elastic energy sum m e(rho) as its internal energy.
#include <algorithm>

#include "core/parallel.h"
#include "core/stages.h"
#include "sph/eos.h"

namespace sph {
namespace {

class EosTait final : public Stage {
 public:
  std::string_view name() const override { return "EOS: Tait"; }
  FieldSet needs() const override { return FieldSet{}.add(Field::Density); }
  FieldSet writes() const override { return FieldSet{}.add(Field::Pressure).add(Field::SoundSpeed); }
  FieldSet shares() const override { return writes(); }
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& rho = p[Field::Density];
    auto& P = p[Field::Pressure];
    auto& cs = p[Field::SoundSpeed];
    const LiquidParams& l = c.prm.liquid;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      P[i] = std::max(l.p_min, eos::tait_pressure(rho[i], l));
      cs[i] = eos::tait_sound_speed(rho[i], l);
    }
    return true;
  }
  double internal_energy(const StageContext& c) const override {
    const auto& m = c.p[Field::Mass];
    const auto& rho = c.p[Field::Density];
    double e = 0.0;
    for (std::size_t i = 0; i < c.p.fluid(); ++i) e += m[i] * eos::tait_energy(rho[i], c.prm.liquid);
    return e;
  }
};

}  // namespace

std::unique_ptr<Stage> make_eos_tait() { return std::make_unique<EosTait>(); }

}  // namespace sph
