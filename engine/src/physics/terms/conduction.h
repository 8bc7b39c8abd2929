// Artificial thermal conductivity (Price 2008, JCP 227, 10040): a term of the energy equation,
//   du_a/dt += sum_b m_b alpha_u v_sig,u (u_a - u_b)/rho_ab dW/dr(mean h),  v_sig,u = sqrt(|P_a - P_b|/rho_ab),
// on when physics.conduction = on with the energy equation and conduction.alpha_u > 0.
#pragma once
#include <cmath>
#include <string_view>

#include "core/stage.h"

namespace sph::terms {

struct Conduction {
  static constexpr std::string_view kName = "conduction";
  bool on;         ///< the scene runs the term
  double alpha_u;  ///< conduction.alpha_u [dimensionless]
  explicit Conduction(const StageContext& c)
      : on(c.prm.physics.energy == Toggle::On && c.prm.physics.conduction == Toggle::On &&
           c.prm.conduction.alpha_u > 0.0),
        alpha_u(c.prm.conduction.alpha_u) {}
  /// The pair's du_a/dt [energy/(mass time)]; dWm = dW/dr at the mean h [1/length^(d+1)].
  double pair(double mj, double ui, double uj, double Pi, double Pj, double rhoi, double rhoj, double dWm) const {
    const double rhom = 0.5 * (rhoi + rhoj);
    const double vsu = std::sqrt(std::abs(Pi - Pj) / rhom);
    return mj * alpha_u * vsu * (ui - uj) / rhom * dWm;
  }
};

}  // namespace sph::terms
