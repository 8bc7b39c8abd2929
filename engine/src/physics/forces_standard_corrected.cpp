// "Standard-corrected" SPH (seed 001 eqs. 53-55): the standard momentum equation with the corrected
// kernel gradients G of corrected_kernel.h, barotropic (no energy equation):
//   dv_a/dt = -sum_b m_b [P_a/rho_a^2 G_a(b) - P_b/rho_b^2 G_b(a) + Pi_ab (G_a(b) - G_b(a))/2]
// Seed 001 eq. 53 evaluates one corrected gradient, at the neighbour; the pair form above (Bonet & Lok
// 1999, §5) is antisymmetric in a and b, so linear momentum is conserved to round-off, and it reduces to
// the standard eq. 44 when L = I and S = 1. The Laplacian viscosity uses r . (G_a(b) - G_b(a))/2.
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "core/stages.h"
#include "courant.h"
#include "continuity_output.h"
#include "pair_loop.h"
#include "pair_standard_corrected.h"
#include "sph/kernel_shapes.h"
#include "terms/visc_terms.h"

namespace sph {
namespace {

using standard_corrected::Factors;

/// Cont: also the continuity rate drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . G_a(b) (seed 001 eq. 54;
/// density_continuity.cpp), in the same pass. In three passes (pair_block.h): the interacting pairs,
/// their terms (vectorised; the kernel's shape fixed at compile time), the sums in list order; the work
/// per particle is pair_standard_corrected.h's.
template <int D, class V, bool Cont, bool Xsph, class Shape>
void standard_corrected_loop(StageContext& c, const Shape& shape, Factors& fac) {
  fac.compute(c.p, c.kernel);
  const standard_corrected::Pairs<D, V, Cont, Xsph, Shape> pairs(c, shape, fac);
  pair_loop(c, pairs, fac.R2.data(), !c.walls_in_sums());
}

template <int D, bool Cont, bool Xsph, class Shape>
void dispatch_visc(StageContext& c, const Shape& s, Factors& f) {
  terms::with_viscosity(c.prm.physics, [&](auto tag) {
    standard_corrected_loop<D, typename decltype(tag)::type, Cont, Xsph>(c, s, f);
  });
}

template <int D>
void dispatch(StageContext& c, bool cont, bool xsph, Factors& f) {
  // the kernel shape is chosen once here, not per pair
  shape::with_shape(c.kernel.type(), D, [&](auto s) {
    if (!cont) dispatch_visc<D, false, false>(c, s, f);
    else if (xsph) dispatch_visc<D, true, true>(c, s, f);
    else dispatch_visc<D, true, false>(c, s, f);
  });
}

/// Reads the momentum equation's fields; writes the signal speed, and the continuity rate when the
/// loop sums it.
StageContract contract(const Physics& ph) {
  StageContract c{.name = "forces: standard-corrected",
                  .needs = {Field::Mass, Field::Density, Field::H, Field::Pressure, Field::SoundSpeed},
                  .writes = {Field::SignalSpeed}};
  if (fuses_continuity(ph)) c.writes.add(Field::DensityRate).add(Field::Neighbours);
  return c;
}

class ForcesStandardCorrected final : public Stage {
 public:
  ForcesStandardCorrected(const Physics& ph, int dim)
      : Stage(contract(ph)), dim_(dim), cont_(fuses_continuity(ph)), xsph_(ph.xsph == Toggle::On) {}
  bool sets_acceleration() const override { return true; }
  bool reads_every_list() const override { return false; }  // the pair loop visits the active rows
  bool run(StageContext& c) override {
    switch (dim_) {
      case 1: dispatch<1>(c, cont_, xsph_, factors_); break;
      case 2: dispatch<2>(c, cont_, xsph_, factors_); break;
      default: dispatch<3>(c, cont_, xsph_, factors_); break;
    }
    return true;
  }
  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }
  void dt_limits(const StageContext& c, std::span<double> dt) const override { courant_limits(c.p, dt); }

 private:
  int dim_;
  bool cont_, xsph_;
  Factors factors_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard_corrected(const Physics& ph, int dim) {
  return std::make_unique<ForcesStandardCorrected>(ph, dim);
}

}  // namespace sph
