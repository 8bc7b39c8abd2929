// Particle sets for the gravity tests: a Plummer sphere and the rho ~ 1/r sphere of seed 003 (eq. 2.42).
#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>

#include "sph/particles.h"

namespace sph::test {

/// splitmix64 uniform numbers in [0, 1).
struct Uniform {
  std::uint64_t s;
  double operator()() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
};

/// n equal masses (total 1) in 3D: Plummer (scale 1, cut at r = 10) or rho ~ 1/r inside R = 1; h set.
inline Particles sphere(std::size_t n, bool plummer, std::uint64_t seed = 7, double h = 0.05) {
  Particles p(3, n, FieldSet{}.add(Field::Mass).add(Field::H));
  Uniform u{seed};
  for (std::size_t i = 0; i < n; ++i) {
    double r;
    do {
      r = plummer ? 1.0 / std::sqrt(std::pow(u(), -2.0 / 3.0) - 1.0) : u();
    } while (plummer ? r > 10.0 : u() > r);
    const double mu = 2.0 * u() - 1.0, phi = 2.0 * std::numbers::pi * u(), s = std::sqrt(1.0 - mu * mu);
    p.x[0][i] = r * s * std::cos(phi);
    p.x[1][i] = r * s * std::sin(phi);
    p.x[2][i] = r * mu;
    p[Field::Mass][i] = 1.0 / static_cast<double>(n);
    p[Field::H][i] = h;
  }
  return p;
}

}  // namespace sph::test
