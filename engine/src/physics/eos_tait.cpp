// Tait/Cole equation of state for a weakly compressible liquid (seed 001 eq. 3; see sph/eos.h), never
// below liquid.p_min, with the elastic energy sum m e(rho) as its internal energy.
#include <algorithm>

#include "core/stages.h"
#include "eos_barotropic.h"
#include "sph/eos.h"

namespace sph {
namespace {

struct Tait {
  explicit Tait(const Params& p) : l(p.liquid) {}
  static std::string_view name() { return "EOS: Tait"; }
  double pressure(double rho) const { return std::max(l.p_min, eos::tait_pressure(rho, l)); }
  double sound_speed(double rho) const { return eos::tait_sound_speed(rho, l); }
  double energy(double rho) const { return eos::tait_energy(rho, l); }
  const LiquidParams& l;
};

}  // namespace

std::unique_ptr<Stage> make_eos_tait() { return std::make_unique<BarotropicEos<Tait>>(); }

}  // namespace sph
