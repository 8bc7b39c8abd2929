// The standard momentum equation, with its fused viscosity, conduction and energy terms:
//   dv_a/dt = -sum_b m_b [P_a/(Omega_a rho_a^2) grad W_ab(h_a) + P_b/(Omega_b rho_b^2) grad W_ab(h_b)
//                         + Pi_ab grad W_ab(mean)]                    (seed 000 eq. 3.3.17; seed 001 eq. 44)
//   du_a/dt = P_a/(Omega_a rho_a^2) sum_b m_b v_ab . grad W_ab(h_a)    (seed 000 eq. 3.3.19)
//           + 1/2 sum_b m_b Pi_ab v_ab . grad W_ab(mean)          (viscous heating: energy conserved)
//           + sum_b m_b alpha_u v_sig,u (u_a - u_b)/rho_ab r_hat . grad W_ab(mean) (Price 2008 conduction)
// Omega = 1 without a summation density (continuity densities have no grad-h terms). The Laplacian
// viscosity adds sum_b m_b (mu_a + mu_b)/(rho_a rho_b) (r.grad W)/(r^2 + eps h^2) v_ab (Morris 1997).
// A gather over the neighbour list: each particle sums its own neighbours in list order.
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "core/stages.h"
#include "courant.h"
#include "continuity_output.h"
#include "pair_loop.h"
#include "pair_standard.h"
#include "sph/kernel_shapes.h"
#include "terms/energy_equation.h"
#include "terms/visc_terms.h"

namespace sph {
namespace {

using standard::Factors;

/// V: the viscosity term (terms/visc_*.h); E: the energy equation on or off (terms/energy_equation.h).
/// Cont: also the continuity rate drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . grad W_ab(h_a) with its
/// density diffusion (density_continuity.cpp), in the same pass (barotropic flows only). Shape: the
/// kernel's shape, fixed at compile time (one instantiation per kernel, chosen once per evaluation).
/// ThreeD = false in 1D and 2D, where z and v_z are 0: the z terms are not computed (each would add
/// +-0 to a sum; the results differ at most in the sign of an exact zero). The work per particle is
/// pair_standard.h's.
template <bool GradH, class V, class E, bool Cont, bool ThreeD, class Shape>
void standard_loop(StageContext& c, const Shape& shape, Factors& fac) {
  fac.compute<GradH>(c.p, c.kernel);
  const standard::Pairs<GradH, V, E, Cont, ThreeD, Shape> pairs(c, shape, fac);
  pair_loop(c, pairs, fac.R2.data(), c.prm.physics.walls == WallType::LennardJones);
}

template <bool GradH, class V, class E, bool Cont, class Shape>
void dispatch_dim(StageContext& c, const Shape& s, Factors& f) {
  if (c.p.dim() == 3) standard_loop<GradH, V, E, Cont, true>(c, s, f);
  else standard_loop<GradH, V, E, Cont, false>(c, s, f);
}

template <bool GradH, class V, class Shape>
void dispatch_energy(StageContext& c, bool energy, bool cont, const Shape& s, Factors& f) {
  if (energy) dispatch_dim<GradH, V, terms::EnergyOn, false>(c, s, f);
  else if (cont && !GradH) dispatch_dim<GradH, V, terms::EnergyOff, true>(c, s, f);
  else dispatch_dim<GradH, V, terms::EnergyOff, false>(c, s, f);
}

template <bool GradH, class Shape>
void dispatch_visc(StageContext& c, bool energy, bool cont, const Shape& s, Factors& f) {
  terms::with_viscosity(c.prm.physics, [&](auto tag) {
    dispatch_energy<GradH, typename decltype(tag)::type>(c, energy, cont, s, f);
  });
}

/// A summation density brings the grad-h terms (Omega).
bool uses_grad_h(const Physics& ph) {
  return ph.density == DensityMode::Summation || ph.density == DensityMode::Volume;
}

/// Reads the momentum equation's fields (Omega with grad-h terms); writes the signal speed, and the
/// continuity rate and dh/dt when the loop sums them.
StageContract contract(const Physics& ph) {
  StageContract c{.name = "forces: standard",
                  .needs = {Field::Mass, Field::Density, Field::H, Field::Pressure, Field::SoundSpeed},
                  .writes = {Field::SignalSpeed}};
  if (uses_grad_h(ph)) c.needs.add(Field::Omega);
  if (fuses_continuity(ph)) c.writes.add(Field::DensityRate).add(Field::Neighbours);
  if (ph.density == DensityMode::Summation && ph.smoothing == HMode::Variable) c.writes.add(Field::HRate);
  return c;
}

class ForcesStandard final : public Stage {
 public:
  explicit ForcesStandard(const Physics& ph)
      : Stage(contract(ph)), grad_h_(uses_grad_h(ph)), energy_(ph.energy == Toggle::On), cont_(fuses_continuity(ph)) {}
  bool sets_acceleration() const override { return true; }
  bool reads_every_list() const override { return false; }  // the pair loop visits the active rows
  bool run(StageContext& c) override {
    // the kernel shape is chosen once here, not per pair
    shape::with_shape(c.kernel.type(), c.p.dim(), [&](auto s) {
      if (grad_h_) dispatch_visc<true>(c, energy_, cont_, s, factors_);
      else dispatch_visc<false>(c, energy_, cont_, s, factors_);
    });
    return true;
  }
  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }
  void dt_limits(const StageContext& c, std::span<double> dt) const override { courant_limits(c.p, dt); }

 private:
  bool grad_h_, energy_, cont_;
  Factors factors_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard(const Physics& ph) { return std::make_unique<ForcesStandard>(ph); }

}  // namespace sph
