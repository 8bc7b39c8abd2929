// Physical viscosity nu with the Laplacian written in first kernel derivatives (seed 004; Morris, Fox &
// Zhu 1997, JCP 136, 214, eq. 8): the term k_ab v_ab of the pair loops, k from pair_terms.h, and its
// heating -1/2 sum_b k_ab |v_ab|^2 in the energy equation.
#pragma once
#include <cstdint>
#include <string_view>

#include "core/stage.h"
#include "physics/pair_terms.h"
#include "visc_parts.h"
#include "wall_friction.h"

namespace sph::terms {

struct ViscLaplacian : ViscParts<false, true> {
  static constexpr std::string_view kName = "Laplacian viscosity";
  double nu, eps;     ///< visc.nu [length^2/time], visc.eps [dimensionless]
  WallFriction wall;  ///< the share between fluid and walls (walls.friction)
  explicit ViscLaplacian(const StageContext& c) : nu(c.prm.visc.nu), eps(c.prm.visc.eps), wall(c) {}
  /// k_ab of the pair with neighbour j: rdW = r_ab . grad W [1/length^d], hm = (h_a + h_b)/2.
  double factor(std::uint32_t j, double mj, double rhoi, double rhoj, double rdW, double r2, double hm) const {
    return wall(j) * pair::laplacian_factor(mj, nu, rhoi, rhoj, rdW, r2, hm, eps);
  }
  /// The work k_ab |v_ab|^2 / 2 the pair's term dissipates, as heat (the loops subtract it from du_a/dt).
  static double work(double k, double dv2) { return 0.5 * k * dv2; }
};

}  // namespace sph::terms
