// Pipeline order: density, smoothing length, EOS, wall pressure, corrections, velocity gradient, XSPH,
// the viscosity switch,
// forces (with viscosity, conduction and the energy equation fused into their loop), continuity rate,
// wall forces, body force, self-gravity and its grad-h term; the finite pointset method runs alone. A slot set to "none" contributes no stage.
#include "core/pipeline.h"

#include "core/stages.h"

namespace sph {

Pipeline::Pipeline(const Params& prm, int dim) {
  const Physics& ph = prm.physics;
  auto add = [&](std::unique_ptr<Stage> s) { if (s) stages_.push_back(std::move(s)); };
  if (ph.density == DensityMode::Summation || ph.density == DensityMode::Volume) add(make_density_summation(ph, dim));
  if (ph.smoothing == HMode::Evolved) add(make_smoothing_evolved(dim));
  switch (ph.eos) {
    case EosType::IdealGas: add(make_eos_ideal_gas()); break;
    case EosType::Tait: add(make_eos_tait()); break;
    case EosType::Isothermal: add(make_eos_isothermal()); break;
    case EosType::Polytropic: add(make_eos_polytropic()); break;
    case EosType::Dfsph: add(make_eos_dfsph()); break;
    case EosType::None: break;
  }
  // DFSPH's walls are in its sums at rest; their pressure is its solve's, not an extrapolated Tait one
  if (ph.walls == WallType::Dummy && ph.eos != EosType::Dfsph) add(make_walls_dummy());
  if (ph.corrected()) add(make_gradient_correction(dim));
  if (ph.force == ForceType::Corrected && ph.viscosity == ViscType::Laplacian) add(make_velocity_gradient(dim));
  if (ph.xsph == Toggle::On) add(make_xsph());
  if (ph.visc_switch != ViscSwitch::None) add(make_viscosity_switch(ph));
  switch (ph.force) {
    case ForceType::Standard: add(make_forces_standard(ph)); break;
    case ForceType::StandardCorrected: add(make_forces_standard_corrected(ph, dim)); break;
    case ForceType::Corrected: add(make_forces_corrected(ph, dim)); break;
    case ForceType::None: break;
  }
  if (ph.viscosity == ViscType::Monaghan) add(make_viscosity_monaghan());
  if (ph.viscosity == ViscType::Laplacian) add(make_viscosity_laplacian());
  if (ph.conduction == Toggle::On) add(make_conduction());
  if (ph.energy == Toggle::On) add(make_energy_equation());
  if (ph.density == DensityMode::Continuity) add(make_density_continuity(ph, dim));
  if (ph.walls == WallType::LennardJones) add(make_walls_lennard_jones());
  if (ph.body_force == BodyForce::Uniform) add(make_body_force_uniform());
  if (ph.body_force == BodyForce::Damping) add(make_body_force_damping());
  if (ph.gravity != GravityType::None) add(make_self_gravity(ph.gravity));
  if (gravity_grad_h(prm)) {
    add(make_gravity_zeta(dim));
    add(make_gravity_grad_h());
  }
  if (ph.fpm != FpmType::None) add(make_fpm_burgers(ph.fpm, dim));

  fields_.add(Field::Mass).add(Field::H);
  for (const auto& s : stages_) {
    fields_ |= s->needs() | s->writes();
    for (const EvolvedPair& e : s->evolves()) {
      fields_.add(e.first).add(e.second);
      evolved_.push_back(e);
    }
    sets_a_ = sets_a_ || s->sets_acceleration();
    uses_neighbours_ = uses_neighbours_ || s->uses_neighbours();
    exact_lists_ = exact_lists_ || s->exact_lists();
    every_list_ = every_list_ || s->reads_every_list();
    if (s->projects()) projector_ = s.get();
  }
  drifts_ = ph.xsph == Toggle::On || ph.fpm == FpmType::BurgersUpwind;
}

}  // namespace sph
