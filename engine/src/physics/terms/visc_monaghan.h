// Monaghan's artificial viscosity with a constant alpha (physics.viscosity = monaghan, visc.switch =
// none): the pair pressure Pi_ab of seed 003 eq. 3.16 (seed 001 eqs. 41-43), added to the pressure
// bracket of the pair loops and heating the gas by 1/2 sum_b m_b Pi_ab v_ab . grad W_ab.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>

#include "core/stage.h"
#include "physics/pair_terms.h"
#include "visc_parts.h"
#include "wall_friction.h"

namespace sph::terms {

struct ViscMonaghan : ViscParts<true, false> {
  static constexpr std::string_view kName = "artificial viscosity Pi";
  double alpha, beta, eps;  ///< visc.alpha, visc.beta, visc.eps [dimensionless]
  WallFriction wall;        ///< the share between fluid and walls (walls.friction)
  /// The viscosity acts as a diffusion of strength ~ alpha c h: beyond alpha = 1, beta = 2 the explicit
  /// limit shrinks in proportion (pair_terms.h signal_speed).
  explicit ViscMonaghan(const StageContext& c)
      : ViscParts{std::max(1.0, c.prm.visc.alpha), std::max(1.0, 0.5 * c.prm.visc.beta)}, alpha(c.prm.visc.alpha),
        beta(c.prm.visc.beta), eps(c.prm.visc.eps), wall(c) {}
  /// Pi_ab of particles i and j [velocity^2/density], without a branch (vectorised loops).
  double pi(std::size_t, std::uint32_t j, double vdotr, double r2, double hi, double hj, double rhoi, double rhoj,
            double ci, double cj) const {
    return wall(j) * pair::monaghan_pi_nb(vdotr, r2, hi, hj, rhoi, rhoj, ci, cj, alpha, beta, eps);
  }
  /// The pair's share of the viscous heating du_a/dt: 1/2 m_b Pi_ab w_ab dW/dr(mean h) [energy/(mass time)].
  static double heat(double mj, double Pi, double w, double dWm) { return 0.5 * mj * Pi * w * dWm; }
};

}  // namespace sph::terms
