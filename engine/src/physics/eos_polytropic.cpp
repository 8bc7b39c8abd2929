// Polytropic gas P = K rho^gamma with gamma = 1 + 1/n (seed 003 eq. 3.72): barotropic, so a polytropic
// star needs no energy equation; c^2 = gamma P / rho; its internal energy int P/rho^2 drho is
// K rho^(gamma-1) / (gamma - 1) (seed 003 eq. 3.79's thermal term).
#include <cmath>

#include "core/stages.h"
#include "eos_barotropic.h"

namespace sph {
namespace {

struct Polytropic {
  explicit Polytropic(const Params& p) : K(p.gas.K), g(p.gas.gamma) {}
  static std::string_view name() { return "EOS: polytropic"; }
  double pressure(double rho) const { return K * std::pow(rho, g); }
  double sound_speed(double rho) const { return std::sqrt(g * K * std::pow(rho, g - 1.0)); }
  double energy(double rho) const { return K * std::pow(rho, g - 1.0) / (g - 1.0); }
  double K, g;
};

}  // namespace

std::unique_ptr<Stage> make_eos_polytropic() { return std::make_unique<BarotropicEos<Polytropic>>(); }

}  // namespace sph
