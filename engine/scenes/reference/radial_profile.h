// Binned radial profiles of the particles about the origin, and the position of a shock front on them:
// what the blast and implosion references measure from the particles.
#pragma once
#include <vector>

#include "sph/particles.h"

namespace sph::scenes {

/// Mean of a field over the real particles in shells [k dr, (k+1) dr) about the origin, k < bins.
struct RadialProfile {
  double dr = 0.0;
  std::vector<double> mean;        ///< the field's mean in each shell (0 where a shell is empty)
  std::vector<std::size_t> count;  ///< particles in each shell
  double centre(std::size_t k) const { return (static_cast<double>(k) + 0.5) * dr; }
};

RadialProfile radial_profile(const Particles& p, Field f, double dr, std::size_t bins);

/// The radius of a shock moving outwards into gas of density `ahead`: from the densest shell outwards,
/// the first place where the shell means fall below half way between that peak and `ahead`, linearly
/// interpolated between shell centres. A step smoothed by a symmetric kernel crosses its half height at
/// the step, so this estimator has no lag of order h (the peak itself sits about h behind the front).
/// Returns 0 if no shell falls below the level or nothing is denser than `ahead`.
double shock_front(const RadialProfile& rho, double ahead);

/// The largest shell mean and its radius (shells with at least `min_count` particles).
struct Peak {
  double value = 0.0, r = 0.0;
};
Peak profile_peak(const RadialProfile& prof, std::size_t min_count);

}  // namespace sph::scenes
