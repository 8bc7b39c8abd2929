// Which stage each run parameter belongs to (params/param_table.cpp): the words that name the stage in
// messages, its slot, and when the chosen physics runs it (a parameter is shown and accepted only then).
#pragma once
#include "params/param_entry.h"

namespace sph::param_owner {

using Owner = param_entry::Common::Owner;

const Owner kVariableH{"the Newton-Raphson smoothing-length solve", Slot::Smoothing,
                       [](const Params& p) { return p.physics.smoothing == HMode::Variable; }};
const Owner kContinuity{"the continuity density", Slot::Density,
                        [](const Params& p) { return p.physics.density == DensityMode::Continuity; }};
const Owner kGammaOwner{"the ideal-gas or polytropic equation of state", Slot::Eos, [](const Params& p) {
                           return p.physics.eos == EosType::IdealGas || p.physics.eos == EosType::Polytropic;
                         }};
const Owner kPolytropic{"the polytropic equation of state", Slot::Eos,
                        [](const Params& p) { return p.physics.eos == EosType::Polytropic; }};
const Owner kDamping{"the damping body force", Slot::BodyForce,
                     [](const Params& p) { return p.physics.body_force == BodyForce::Damping; }};
const Owner kIsothermal{"the isothermal equation of state", Slot::Eos,
                        [](const Params& p) { return p.physics.eos == EosType::Isothermal; }};
const Owner kTait{"the Tait equation of state", Slot::Eos, [](const Params& p) { return p.physics.eos == EosType::Tait; }};
const Owner kDfsph{"the incompressible pressure solve (DFSPH)", Slot::Eos,
                   [](const Params& p) { return p.physics.eos == EosType::Dfsph; }};
const Owner kLiquid{"the liquid (Tait or DFSPH)", Slot::Eos,
                    [](const Params& p) { return p.physics.eos == EosType::Tait || p.physics.eos == EosType::Dfsph; }};
const Owner kIntegrated{"the time integrator (DFSPH steps by its own symplectic Euler)", Slot::Eos,
                        [](const Params& p) { return p.physics.eos != EosType::Dfsph; }};
const Owner kMonaghan{"the Monaghan viscosity stage", Slot::Viscosity,
                      [](const Params& p) { return p.physics.viscosity == ViscType::Monaghan; }};
const Owner kConstantAlpha{"the Monaghan viscosity with a constant or Balsara-limited alpha", Slot::Viscosity,
                           [](const Params& p) {
                             return p.physics.viscosity == ViscType::Monaghan &&
                                    p.physics.visc_switch != ViscSwitch::CullenDehnen;
                           }};
const Owner kSwitchable{"the Monaghan viscosity of the standard and standard-corrected forces", Slot::Viscosity,
                        [](const Params& p) {
                          const Physics& ph = p.physics;
                          return ph.viscosity == ViscType::Monaghan &&
                                 (ph.force == ForceType::Standard || ph.force == ForceType::StandardCorrected);
                        }};
const Owner kCullenDehnen{"the Cullen-Dehnen viscosity switch (visc.switch = cullen_dehnen)", Slot::Viscosity,
                          [](const Params& p) { return p.physics.visc_switch == ViscSwitch::CullenDehnen; }};
const Owner kLaplacian{"the Laplacian viscosity stage", Slot::Viscosity,
                       [](const Params& p) { return p.physics.viscosity == ViscType::Laplacian; }};
const Owner kAnyViscosity{"a viscosity stage", Slot::Viscosity,
                          [](const Params& p) { return p.physics.viscosity != ViscType::None; }};
const Owner kConduction{"the conduction stage", Slot::Conduction,
                        [](const Params& p) { return p.physics.conduction == Toggle::On; }};
const Owner kXsph{"the XSPH stage", Slot::Xsph, [](const Params& p) { return p.physics.xsph == Toggle::On; }};
const Owner kBody{"the body-force stage", Slot::BodyForce,
                  [](const Params& p) { return p.physics.body_force == BodyForce::Uniform; }};
const Owner kGravity{"the self-gravity stage", Slot::Gravity,
                     [](const Params& p) { return p.physics.gravity != GravityType::None; }};
const Owner kFmm{"the fast multipole method", Slot::Gravity, [](const Params& p) { return p.physics.gravity == GravityType::Fmm; }};
const Owner kTree{"the Barnes-Hut tree", Slot::Gravity, [](const Params& p) { return p.physics.gravity == GravityType::Tree; }};
const Owner kPlummer{"Plummer-softened self-gravity", Slot::Gravity, [](const Params& p) {
                       return p.physics.gravity != GravityType::None && p.gravity.softening == Softening::Plummer;
                     }};
const Owner kKernel{"the SPH kernel (SPH stages or kernel-softened gravity)", Slot::Density, [](const Params& p) {
                      const Physics& ph = p.physics;
                      return ph.density != DensityMode::None || ph.force != ForceType::None || ph.xsph == Toggle::On ||
                             (ph.gravity != GravityType::None && kernel_softened(p.gravity.softening));
                    }};
const Owner kFpm{"the finite pointset method", Slot::Fpm, [](const Params& p) { return p.physics.fpm != FpmType::None; }};
const Owner kFpmViscous{"the viscous Burgers scheme", Slot::Fpm,
                        [](const Params& p) { return p.physics.fpm == FpmType::BurgersViscous; }};
const Owner kLJ{"the Lennard-Jones wall stage", Slot::Walls,
                [](const Params& p) { return p.physics.walls == WallType::LennardJones; }};
const Owner kWallFriction{"a viscosity stage with dummy walls", Slot::Walls, [](const Params& p) {
                           return p.physics.walls == WallType::Dummy && p.physics.viscosity != ViscType::None;
                         }};
const Owner kCorrected{"the kernel corrections (corrected formulations, MLS density re-initialisation)", Slot::Force,
                       [](const Params& p) {
                         return p.physics.corrected() ||
                                (p.physics.density == DensityMode::Continuity && p.density.reinit_every > 0);
                       }};

}  // namespace sph::param_owner
