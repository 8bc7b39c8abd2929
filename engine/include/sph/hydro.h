// Compressible SPH: equation of state, momentum and energy equations with grad-h terms and
// Monaghan artificial viscosity (seed 000 eqs. 3.3.17, 3.3.19, 3.3.23; seed 003 eq. 3.16).
#pragma once
#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

/// P = (gamma-1) rho u (seed 000 eq. 3.3.23) and c = sqrt(gamma P/rho) for the real particles.
void ideal_gas_eos(const Params& prm, Particles& p);

/// Accelerations a, du/dt and the signal speed of every real particle (gather over the neighbour
/// list; ghosts must already carry rho, h, Omega, P, c, u and v):
///   dv_a/dt = -sum_b m_b [P_a/(Omega_a rho_a^2) grad W_ab(h_a) + P_b/(Omega_b rho_b^2) grad W_ab(h_b)
///                         + Pi_ab gradW_ab(mean)]                               (seed 000 eq. 3.3.17)
///   du_a/dt = P_a/(Omega_a rho_a^2) sum_b m_b v_ab . grad W_ab(h_a)             (seed 000 eq. 3.3.19)
///           + 1/2 sum_b m_b Pi_ab v_ab . gradW_ab(mean)          (viscous heating: energy conserved)
///           + sum_b m_b alpha_u v_sig,u (u_a - u_b)/rho_ab r_hat . gradW_ab(mean) (Price 2008 conduction)
/// Pi_ab = (-alpha c_ab mu_ab + beta mu_ab^2)/rho_ab if v_ab.r_ab < 0, mu_ab = h_ab v_ab.r_ab/(r^2 + eps h_ab^2)
/// (seed 003 eq. 3.16). energy=false skips du/dt (no energy equation in the scene).
void hydro_forces(const Kernel& kernel, const Params& prm, Particles& p, const NeighbourList& nl, bool energy);

}  // namespace sph
