// Explicit (forward) Euler: first order, for teaching; x uses the old velocity.
#include "phase_ops.h"

namespace sph {

class EulerIntegrator final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    if (!current) eval(0.0);
    for (int k = 0; k < s.dim; ++k) {
      detail::drift(s, k, *s.x[k], *s.x[k], dt, *s.v[k]);
      detail::axpy(*s.v[k], *s.v[k], dt, *s.a[k], s.n);
    }
    for (const EvolvedArray& e : s.evolved) detail::axpy(*e.y, *e.y, dt, *e.rate, s.n);
    return false;
  }
};

std::unique_ptr<Integrator> make_euler() { return std::make_unique<EulerIntegrator>(); }

}  // namespace sph
