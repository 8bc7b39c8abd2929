// Isothermal gas P = cs^2 rho (the n -> infinity polytrope of seed 003 eq. 3.72); its internal energy,
// int P/rho^2 drho, is cs^2 ln(rho) up to a constant: sum m cs^2 ln(rho) is reported.
#include <cmath>

#include "core/stages.h"
#include "eos_barotropic.h"

namespace sph {
namespace {

struct Isothermal {
  explicit Isothermal(const Params& p) : c2(p.gas.cs * p.gas.cs), c(p.gas.cs) {}
  static std::string_view name() { return "EOS: isothermal"; }
  double pressure(double rho) const { return c2 * rho; }
  double sound_speed(double) const { return c; }
  double energy(double rho) const { return c2 * std::log(rho); }
  double c2, c;
};

}  // namespace

std::unique_ptr<Stage> make_eos_isothermal() { return std::make_unique<BarotropicEos<Isothermal>>(); }

}  // namespace sph
