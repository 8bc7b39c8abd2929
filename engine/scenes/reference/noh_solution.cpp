#include "reference/noh_solution.h"

#include <cmath>

namespace sph::scenes {

double Noh::post_shock_density() const { return rho0 * std::pow((gamma + 1.0) / (gamma - 1.0), dim); }

NohState Noh::state(double r, double t) const {
  if (r < shock_radius(t)) {
    const double u2 = 0.5 * v0 * v0;  // all the inflow's kinetic energy, thermalised
    return {post_shock_density(), 0.0, (gamma - 1.0) * post_shock_density() * u2, u2};
  }
  // ahead of the shock: free (pressureless) convergence, mass conservation along r + v0 t = const
  return {rho0 * std::pow(1.0 + v0 * t / r, dim - 1), -v0, 0.0, 0.0};
}

}  // namespace sph::scenes
