// Per-pair maths shared by the force loops: Monaghan's artificial viscosity, the Laplacian viscosity
// written with first kernel derivatives, and the pair signal speed. Pure inline functions.
#pragma once
#include <algorithm>

#include "sph/kernel.h"

namespace sph::pair {

/// W and dW/dr at distance r for particle a's h (factors sa) and for b's h_b; with a fixed h (h_b = h_a)
/// the second pair is the first, not evaluated again.
inline void kernels(const Kernel& K, const Kernel::Scale& sa, double ha, double hb, double r, double& Wa,
                    double& dWa, double& Wb, double& dWb) {
  K.eval(sa, r, Wa, dWa);
  if (hb == ha) {
    Wb = Wa;
    dWb = dWa;
  } else {
    K.eval(K.scale(hb), r, Wb, dWb);
  }
}

/// Monaghan Pi_ab for an approaching pair (v_ab . r_ab < 0), 0 otherwise (seed 003 eq. 3.16; seed 001
/// eqs. 41-43): mu = h_ab v_ab.r_ab / (r^2 + eps h_ab^2), Pi = (-alpha c_ab mu + beta mu^2) / rho_ab.
inline double monaghan_pi(double vdotr, double r2, double hi, double hj, double rhoi, double rhoj, double ci,
                          double cj, double alpha, double beta, double eps) {
  if (vdotr >= 0.0) return 0.0;
  const double hm = 0.5 * (hi + hj);
  const double mu = hm * vdotr / (r2 + eps * hm * hm);
  const double rhom = 0.5 * (rhoi + rhoj);
  const double cm = 0.5 * (ci + cj);
  return (-alpha * cm * mu + beta * mu * mu) / rhom;
}

/// monaghan_pi without a branch: both sides evaluated, the same value (for vectorised pair loops, where
/// a receding pair costs a lane, not a mispredicted branch).
inline double monaghan_pi_nb(double vdotr, double r2, double hi, double hj, double rhoi, double rhoj, double ci,
                             double cj, double alpha, double beta, double eps) {
  const double hm = 0.5 * (hi + hj);
  const double mu = hm * vdotr / (r2 + eps * hm * hm);
  const double rhom = 0.5 * (rhoi + rhoj);
  const double cm = 0.5 * (ci + cj);
  const double pi = (-alpha * cm * mu + beta * mu * mu) / rhom;
  return vdotr >= 0.0 ? 0.0 : pi;
}

/// Signal speed of a pair for the Courant limit (Monaghan 1997): c_ab - 2 w_ab for approaching pairs
/// (w = v_ab . r_hat). The viscosity acts as a diffusion of strength ~ alpha c h (and beta |w| h), so
/// beyond alpha = 1, beta = 2 the explicit limit shrinks in proportion (alpha = 8 ran unstably without).
inline double signal_speed(double ci, double cj, double w, double alpha_scale, double beta_scale) {
  return 0.5 * (ci + cj) * alpha_scale + beta_scale * std::max(0.0, -2.0 * w);
}

/// Laplacian viscosity from first derivatives (seed 004; Morris, Fox & Zhu 1997, JCP 136, 214, eq. 8):
/// (1/rho) div(mu grad v) ~ sum_b m_b (mu_a + mu_b)/(rho_a rho_b) (r_ab . grad W_ab)/(r^2 + eps h^2) v_ab,
/// with mu = rho nu. Returns the factor of v_ab; rdW = r_ab . grad_a W_ab [1/length^d].
inline double laplacian_factor(double mj, double nu, double rhoi, double rhoj, double rdW, double r2, double hm,
                               double eps) {
  return mj * nu * (rhoi + rhoj) / (rhoi * rhoj) * rdW / (r2 + eps * hm * hm);
}

/// Density diffusion of the continuity equation (Molteni & Colagrossi 2009, Comput. Phys. Commun. 180,
/// 861; the "delta-SPH" term): drho_a/dt += 2 delta h_a c0 sum_b V_b (rho_a - rho_b) (dW/dr)/r. It smooths
/// the density, hence the pressure, the way a Laplacian of rho would; summed per pair without 2 delta h c0.
/// dW_r = dW/dr(r, h_a) / r [1/length^(d+2)].
inline double density_diffusion(double Vj, double rhoi, double rhoj, double dW_r) { return Vj * (rhoi - rhoj) * dW_r; }

}  // namespace sph::pair
