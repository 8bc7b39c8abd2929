// The laws of the viscosity switches (visc.switch), per particle and free of the particles' storage, so
// tests can take them apart: Balsara's shear limiter and the Cullen-Dehnen alpha.
#pragma once
#include <algorithm>
#include <cmath>

namespace sph::terms {

/// Balsara (1995, JCP 121, 357) f = |div v| / (|div v| + |curl v| + 1e-4 c/h): 1 in pure compression,
/// 0 in pure shear or rotation. div v and |curl v| [1/time], c [length/time], h [length].
inline double balsara_factor(double divv, double curl, double c, double h) {
  const double a = std::abs(divv);
  const double d = a + curl + 1e-4 * c / h;
  return d > 0.0 ? a / d : 0.0;
}

/// Cullen & Dehnen (2010, MNRAS 408, 669) alpha, in the simplified form of Phantom (Price et al. 2018,
/// PASA 35, e031) with the time derivative of div v taken over the last interval as SWIFT's
/// SPHENIX does (Borrow et al. 2022, MNRAS 511, 2367):
///   A = xi max(-d(div v)/dt, 0) in compression (div v < 0), 0 otherwise; xi = (div v)^2 / ((div v)^2 + |curl v|^2)
///   alpha_loc = alpha_max H^2 A / (H^2 A + c^2)
///   alpha = alpha_loc where alpha_loc > alpha_old (at once, ahead of a shock); otherwise alpha decays to
///   alpha_loc on tau = H / (decay c), integrated exactly over dt: alpha_loc + (alpha_old - alpha_loc) e^(-dt/tau)
/// and alpha is kept in [alpha_min, alpha_max]. dt = 0 (no earlier evaluation) keeps alpha_old. H is the
/// radius of the kernel's support (support x h), the "h" of Cullen & Dehnen and SPHENIX: with h itself
/// (Phantom's convention) alpha reached only 0.37 at Sod's shock, with H 0.61.
struct CullenDehnenLaw {
  double alpha_min, alpha_max, decay;  ///< visc.alpha_min, visc.alpha_max, visc.decay [dimensionless]

  double local(double divv, double divv_old, double curl, double dt, double c, double H) const {
    if (!(dt > 0.0) || !(divv < 0.0)) return 0.0;
    const double ddiv = (divv - divv_old) / dt;  // d(div v)/dt [1/time^2]
    const double d2 = divv * divv;
    const double xi = d2 / (d2 + curl * curl);
    const double s = H * H * xi * std::max(-ddiv, 0.0);  // [length^2/time^2]
    return s > 0.0 ? alpha_max * s / (s + c * c) : 0.0;
  }
  double next(double alpha_old, double divv, double divv_old, double curl, double dt, double c, double H) const {
    const double loc = local(divv, divv_old, curl, dt, c, H);
    double a = alpha_old;
    if (loc > alpha_old) {
      a = loc;
    } else if (dt > 0.0 && c > 0.0) {
      const double tau = H / (decay * c);  // [time]
      a = loc + (alpha_old - loc) * std::exp(-dt / tau);
    }
    return std::clamp(a, alpha_min, std::max(alpha_min, alpha_max));
  }
};

}  // namespace sph::terms
