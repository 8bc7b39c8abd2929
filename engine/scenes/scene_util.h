// Helpers shared by the scene builders.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "sph/scene.h"

namespace sph::scenes {

/// Portable uniform random numbers in [0,1) from a 64-bit seed (splitmix64; same on every platform,
/// unlike std::uniform_real_distribution).
class Random {
 public:
  explicit Random(std::uint64_t seed) : s_(seed) {}
  double uniform() {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t s_;
};

/// n fluid particles in dimension dim with every field the stages of prm.physics use allocated.
Particles make_particles(const Params& prm, int dim, std::size_t n);

/// Effective eta for a scene's params (kernel default if eta == 0).
double effective_eta(const Params& prm, int dim);

/// A scene that runs no SPH stage (N-body, the finite pointset method): density, EOS, forces,
/// viscosity and energy set to none (and only none accepted, as for XSPH, conduction, body force and
/// walls), h fixed.
void without_sph(SceneSpec& s);

/// A scene's identity: its name, category, one-line description, dimension and units (code units unless
/// given); everything else at its default.
SceneSpec scene_head(std::string name, std::string category, std::string description, int dim,
                     UnitSystem units = {});

/// The common start of a gas test scene: ideal gas only, no walls, the given kernel, gamma and
/// Monaghan viscosity (alpha, beta); the caller adds the rest.
SceneSpec gas_test_scene(std::string name, std::string category, std::string description, int dim, KernelType kernel,
                         double gamma, double alpha, double beta);

/// A scene's default run: to t_end, with an output every dt_out (both in the scene's time unit).
inline void set_run_times(Params& d, double t_end, double dt_out) {
  d.time.t_end = t_end;
  d.time.dt_out = dt_out;
}

/// The scene parameter "seed" (default 1) of a random placement; `description` says what it seeds.
inline SceneParam seed_param(std::string description) {
  return {"seed", 1, 0, 1e9, true, std::move(description), "dimensionless (random seed)"};
}

/// Sets u from pressure for an ideal gas: u = P / ((gamma - 1) rho).
/// The reference guard's resolution bound: the scene's error bounds were measured at [lo, hi] of a
/// resolution value (particles per side, or a spacing); outside, its errors grow by the method's order.
inline RefAssumption resolution(std::string key, double lo, double hi) {
  return {std::move(key), lo, hi, "the error bounds were measured at this resolution or finer", {}};
}

inline double energy_from_pressure(double P, double rho, double gamma) { return P / ((gamma - 1.0) * rho); }

}  // namespace sph::scenes
