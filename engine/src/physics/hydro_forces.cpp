// Momentum and energy equations with grad-h terms and artificial dissipation (see sph/hydro.h).
#include <algorithm>
#include "core/parallel.h"
#include <cmath>

#include "sph/hydro.h"

namespace sph {

void hydro_forces(const Kernel& K, const Params& prm, Particles& p, const NeighbourList& nl, bool energy) {
  const std::size_t n = p.size();
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  const auto& omega = p[Field::Omega];
  const auto& P = p[Field::Pressure];
  const auto& c = p[Field::SoundSpeed];
  auto& vsig = p[Field::SignalSpeed];
  const std::vector<double>* u = p.has(Field::Energy) ? &p[Field::Energy] : nullptr;
  std::vector<double>* dudt = energy ? &p[Field::EnergyRate] : nullptr;
  const double alpha = prm.alpha, beta = prm.beta, eps = prm.visc_eps, alpha_u = prm.alpha_u;
  const double support = K.support();
  const double alpha_scale = std::max(1.0, alpha), beta_scale = std::max(1.0, 0.5 * beta);

#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = p.x[0][i], yi = p.x[1][i], zi = p.x[2][i];
    const double vxi = p.v[0][i], vyi = p.v[1][i], vzi = p.v[2][i];
    const double hi = h[i];
    const double Ai = P[i] / (omega[i] * rho[i] * rho[i]);  // P_a/(Omega_a rho_a^2)
    double ax = 0.0, ay = 0.0, az = 0.0, du = 0.0, visc_heat = 0.0, cond = 0.0;
    double vs = c[i];
    for (std::uint32_t j : nl.of(i)) {
      if (j == i) continue;
      const double dx = xi - p.x[0][j], dy = yi - p.x[1][j], dz = zi - p.x[2][j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double hj = h[j];
      const double R = support * std::max(hi, hj);
      if (r2 >= R * R || r2 == 0.0) continue;
      const double r = std::sqrt(r2);
      const double rinv = 1.0 / r;
      const double dWi = K.dWdr(r, hi), dWj = K.dWdr(r, hj);  // dW/dr; grad W = r_hat dW/dr
      const double dWm = 0.5 * (dWi + dWj);
      const double Aj = P[j] / (omega[j] * rho[j] * rho[j]);
      const double vdotr = (vxi - p.v[0][j]) * dx + (vyi - p.v[1][j]) * dy + (vzi - p.v[2][j]) * dz;
      double Pi = 0.0;
      if (vdotr < 0.0) {  // approaching pair: Monaghan viscosity (seed 003 eq. 3.16)
        const double hm = 0.5 * (hi + hj);
        const double mu = hm * vdotr / (r2 + eps * hm * hm);
        const double rhom = 0.5 * (rho[i] + rho[j]);
        const double cm = 0.5 * (c[i] + c[j]);
        Pi = (-alpha * cm * mu + beta * mu * mu) / rhom;
      }
      // signal speed for the CFL limit (Monaghan 1997): c_ab - 2 w_ab for approaching pairs. The viscosity
      // acts as a diffusion of strength ~ alpha c h (and beta |w| h), so beyond alpha = 1, beta = 2 the
      // explicit limit shrinks in proportion: without this, alpha = 8 ran unstably with E_tot growing.
      const double w = vdotr * rinv;
      vs = std::max(vs, 0.5 * (c[i] + c[j]) * alpha_scale + beta_scale * std::max(0.0, -2.0 * w));
      const double f = -m[j] * (Ai * dWi + Aj * dWj + Pi * dWm) * rinv;  // times r_vec below
      ax += f * dx;
      ay += f * dy;
      az += f * dz;
      if (dudt) {
        du += m[j] * w * dWi;                    // times Ai below (seed 000 eq. 3.3.19)
        visc_heat += 0.5 * m[j] * Pi * w * dWm;  // dissipated kinetic energy goes to heat
        if (alpha_u > 0.0) {
          const double rhom = 0.5 * (rho[i] + rho[j]);
          const double vsu = std::sqrt(std::abs(P[i] - P[j]) / rhom);
          cond += m[j] * alpha_u * vsu * ((*u)[i] - (*u)[j]) / rhom * dWm;
        }
      }
    }
    p.a[0][i] = ax;
    p.a[1][i] = ay;
    p.a[2][i] = az;
    vsig[i] = vs;
    if (dudt) (*dudt)[i] = Ai * du + visc_heat + cond;
  }
}

}  // namespace sph
