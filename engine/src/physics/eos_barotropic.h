// The shape of a barotropic EOS stage (P and c from rho alone): Tait, isothermal. The Model supplies
// name(), pressure(rho), sound_speed(rho) and energy(rho) (specific internal energy, int P/rho^2 drho).
#pragma once
#include <algorithm>

#include "core/parallel.h"
#include "core/stage.h"

namespace sph {

template <class Model>
class BarotropicEos final : public Stage {
 public:
  bool reads_every_list() const override { return false; }  // reads no lists
  BarotropicEos()
      : Stage({.name = Model::name(),
               .needs = {Field::Density},
               .writes = {Field::Pressure, Field::SoundSpeed},
               .shares = {Field::Pressure, Field::SoundSpeed}}) {}
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& rho = p[Field::Density];
    auto& P = p[Field::Pressure];
    auto& cs = p[Field::SoundSpeed];
    const Model model(c.prm);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      P[i] = model.pressure(rho[i]);
      cs[i] = model.sound_speed(rho[i]);
    }
    return true;
  }
  double internal_energy(const StageContext& c) const override {
    const auto& m = c.p[Field::Mass];
    const auto& rho = c.p[Field::Density];
    const Model model(c.prm);
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < c.p.fluid(); ++i) e += m[i] * model.energy(rho[i]);
    return e;
  }
};

}  // namespace sph
