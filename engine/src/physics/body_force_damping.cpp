// Damping a -= v / tau: removes kinetic energy on the time scale tau, so a state relaxes to a static
// equilibrium (the polytrope's set-up; Lucy 1977, Price 2012 §6). Not a physical force: it conserves
// neither energy nor momentum and has no potential.
#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class BodyForceDamping final : public Stage {
 public:
  BodyForceDamping() : Stage({.name = "body force: damping -v/tau"}) {}
  bool uses_neighbours() const override { return false; }
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const double rate = 1.0 / c.prm.body.tau;
    for (int k = 0; k < p.dim(); ++k) {
      auto& a = p.a[k];
      const auto& v = p.v[k];
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
      for (std::size_t i = 0; i < n; ++i) a[i] -= rate * v[i];
    }
    return true;
  }
  /// Stable for dt < 2 tau (explicit decay); the Courant factor keeps dt below tau.
  double dt_limit(const StageContext& c) const override { return c.prm.body.tau; }
};

}  // namespace

std::unique_ptr<Stage> make_body_force_damping() { return std::make_unique<BodyForceDamping>(); }

}  // namespace sph
