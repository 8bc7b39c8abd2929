// The internal energy equation of the standard grad-h form (seed 000 eq. 3.3.19):
//   du_a/dt = P_a/(Omega_a rho_a^2) sum_b m_b v_ab . grad W_ab(h_a) + viscous heating + conduction.
// Off: the loop sums no energy terms (barotropic flows, where P depends on rho alone).
#pragma once
#include <string_view>

namespace sph::terms {

struct EnergyOff {
  static constexpr bool kOn = false;
};

struct EnergyOn {
  static constexpr bool kOn = true;
  static constexpr std::string_view kName = "pressure work P/rho^2 drho";
  /// m_b v_ab . grad W_ab(h_a) of one pair: w = v_ab . r_hat [length/time], dWi = dW/dr(h_a).
  static double pair(double mj, double w, double dWi) { return mj * w * dWi; }
  /// du_a/dt from the sums: Ai = P_a/(Omega_a rho_a^2), work = sum of pair(), heat and cond the terms' sums.
  static double rate(double Ai, double work, double heat, double cond) { return Ai * work + heat + cond; }
};

}  // namespace sph::terms
