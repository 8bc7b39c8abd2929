// Two point masses from a given relative position r0 and velocity v0 under mu = G (m1 + m2): their
// separation against time (the relative orbit r'' = -mu r / |r|^3 of seed 003 §2.3.1 and §2.4.1),
// tabulated once by RK4 with a step of 1e-3 of the local dynamical time sqrt(|r|^3 / mu), so a head-on
// fall is followed down to small r, and interpolated with the separation's rate. Any energy (bound,
// parabolic or hyperbolic) and any impact parameter.
#pragma once
#include <vector>

#include "sph/vec.h"

namespace sph::scenes {

class TwoBodyOrbit {
 public:
  /// Tabulates up to t_max or until the separation falls below r_min [length].
  TwoBodyOrbit(Vec3 r0, Vec3 v0, double mu, double t_max, double r_min);
  /// Separation at time t (cubic Hermite in the table); nan beyond its end.
  double separation(double t) const;
  /// The first time the separation falls to r (0 if it starts there); nan if it does not within the table.
  double time_to(double r) const;

 private:
  std::vector<double> t_, r_, dr_;  ///< time, separation and its rate at each step
};

}  // namespace sph::scenes
