// The particle fields the pair loops read, as plain arrays over every particle (ghosts included): the
// kernel sums' m, rho and h, and the force loops' P, c_s and the signal speed they write.
#pragma once
#include "sph/particles.h"

namespace sph {

/// m [mass], rho [mass/length^d] and h [length] of every particle.
struct KernelFields {
  const double* m;
  const double* rho;
  const double* h;
  explicit KernelFields(const Particles& p)
      : m(p[Field::Mass].data()), rho(p[Field::Density].data()), h(p[Field::H].data()) {}
};

/// The force loops' fields: those of the kernel sums, P and c_s, and v_sig, which they write.
struct ForceFields : KernelFields {
  const double* P;   ///< pressure
  const double* cs;  ///< sound speed [length/time]
  double* vsig;      ///< the pair signal speed's maximum over the neighbours (courant.h)
  explicit ForceFields(Particles& p)
      : KernelFields(p), P(p[Field::Pressure].data()), cs(p[Field::SoundSpeed].data()),
        vsig(p[Field::SignalSpeed].data()) {}
};

/// P_a/(Omega_a rho_a^2), the pressure factor of the momentum equation (Omega = 1 without grad-h terms).
inline double pressure_factor(double P, double omega, double rho) { return P / (omega * rho * rho); }

}  // namespace sph
