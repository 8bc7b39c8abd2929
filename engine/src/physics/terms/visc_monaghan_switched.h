// Monaghan's artificial viscosity with alpha per particle (visc.switch = balsara | cullen_dehnen): the
// switch stage (physics/viscosity_switch.cpp) writes alpha_a into Field::ViscAlpha, and the pair uses
// alpha_ab = (alpha_a + alpha_b)/2 in both terms of Pi (seed 003 eq. 3.16):
//   Pi_ab = (-alpha_ab c_ab mu_ab + beta (alpha_ab / alpha_ref) mu_ab^2) / rho_ab,
// alpha_ref = visc.alpha (Balsara) or visc.alpha_max (Cullen-Dehnen), so alpha_ab = alpha_ref gives the
// constant-alpha Pi; the quadratic term scales with alpha as in Phantom and SPHENIX, where alpha
// multiplies the whole signal velocity (Price et al. 2018, PASA 35, e031).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string_view>

#include "core/stage.h"
#include "physics/pair_terms.h"
#include "visc_monaghan.h"

namespace sph::terms {

struct ViscMonaghanSwitched : ViscParts<true, false> {
  static constexpr std::string_view kName = "artificial viscosity Pi (alpha per particle)";
  double beta_ref, eps;  ///< beta / alpha_ref [dimensionless], visc.eps
  const double* alpha;   ///< alpha of every particle, ghosts included
  WallFriction wall;     ///< the share between fluid and walls (walls.friction)
  static double reference(const Params& p) {
    return p.physics.visc_switch == ViscSwitch::CullenDehnen ? p.visc.alpha_max : p.visc.alpha;
  }
  explicit ViscMonaghanSwitched(const StageContext& c)
      : ViscParts{std::max(1.0, reference(c.prm)), std::max(1.0, 0.5 * c.prm.visc.beta)},
        beta_ref(reference(c.prm) > 0.0 ? c.prm.visc.beta / reference(c.prm) : 0.0), eps(c.prm.visc.eps),
        alpha(c.p[Field::ViscAlpha].data()), wall(c) {}
  double pi(std::size_t i, std::uint32_t j, double vdotr, double r2, double hi, double hj, double rhoi, double rhoj,
            double ci, double cj) const {
    const double a = 0.5 * (alpha[i] + alpha[j]);
    return wall(j) * pair::monaghan_pi_nb(vdotr, r2, hi, hj, rhoi, rhoj, ci, cj, a, beta_ref * a, eps);
  }
  static double heat(double mj, double Pi, double w, double dWm) { return ViscMonaghan::heat(mj, Pi, w, dWm); }
};

}  // namespace sph::terms
