// Factories of the stage options, one per file under physics/ and boundaries/ (see core/stage.h).
#pragma once
#include <memory>

#include "core/stage.h"

namespace sph {

std::unique_ptr<Stage> make_density_summation(const Physics& ph, int dim);  // summation | volume, variable | fixed h
std::unique_ptr<Stage> make_density_continuity(const Physics& ph, int dim);
/// The continuity rate is summed inside the force loop (one pass over the neighbours instead of two):
/// for the barotropic standard and standard-corrected loops. The continuity stage then only declares it.
inline bool fuses_continuity(const Physics& ph) {
  if (ph.density != DensityMode::Continuity) return false;
  return ph.force == ForceType::StandardCorrected || (ph.force == ForceType::Standard && ph.energy == Toggle::Off);
}
std::unique_ptr<Stage> make_smoothing_evolved(int dim);
std::unique_ptr<Stage> make_eos_ideal_gas();
std::unique_ptr<Stage> make_eos_tait();
std::unique_ptr<Stage> make_eos_isothermal();
std::unique_ptr<Stage> make_eos_polytropic();
std::unique_ptr<Stage> make_eos_dfsph();  // the incompressible pressure solve (physics/dfsph_solver.h)
std::unique_ptr<Stage> make_walls_dummy();
std::unique_ptr<Stage> make_gradient_correction(int dim);
std::unique_ptr<Stage> make_velocity_gradient(int dim);
std::unique_ptr<Stage> make_xsph();
std::unique_ptr<Stage> make_viscosity_switch(const Physics& ph);  // visc.switch: balsara | cullen_dehnen
std::unique_ptr<Stage> make_forces_standard(const Physics& ph);
std::unique_ptr<Stage> make_forces_standard_corrected(const Physics& ph, int dim);
std::unique_ptr<Stage> make_forces_corrected(const Physics& ph, int dim);
std::unique_ptr<Stage> make_viscosity_monaghan();
std::unique_ptr<Stage> make_viscosity_laplacian();
std::unique_ptr<Stage> make_conduction();
std::unique_ptr<Stage> make_energy_equation();
std::unique_ptr<Stage> make_walls_lennard_jones();
std::unique_ptr<Stage> make_body_force_uniform();
std::unique_ptr<Stage> make_body_force_damping();
std::unique_ptr<Stage> make_self_gravity(GravityType type);  // direct | tree
/// The grad-h term of kernel-softened gravity: zeta, then its force (physics/gravity_grad_h.cpp).
std::unique_ptr<Stage> make_gravity_zeta(int dim);
std::unique_ptr<Stage> make_gravity_grad_h();
/// Whether a run takes the grad-h term: kernel softening of h from the summation density's solve.
inline bool gravity_grad_h(const Params& p) {
  const Physics& ph = p.physics;
  return ph.gravity != GravityType::None && p.gravity.softening == Softening::Kernel &&
         ph.density == DensityMode::Summation && ph.smoothing == HMode::Variable;
}
std::unique_ptr<Stage> make_fpm_burgers(FpmType type, int dim);  // seed 002: viscous | upwind

}  // namespace sph
