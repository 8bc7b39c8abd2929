// Leapfrog kick-drift-kick: symplectic and time reversible for conservative forces (seed 003 §2
// recommends a symplectic Stoermer-Verlet scheme for long runs; seed 004). One evaluation per step.
// The evaluation after the drift sees the predicted v + dt/2 a_old and u + dt/2 du_old, as usual for
// velocity-dependent SPH forces.
#include "phase_ops.h"

namespace sph {

class LeapfrogIntegrator final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    if (!current) eval();
    const std::size_t n = s.n;
    const double half = 0.5 * dt;
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], *s.v[k], half, *s.a[k], n);  // kick: v_{1/2}
      detail::axpy(*s.x[k], *s.x[k], dt, *s.v[k], n);     // drift: x_1
      detail::copy(vhalf_[k], *s.v[k], n);
      detail::axpy(*s.v[k], vhalf_[k], half, *s.a[k], n);  // predicted v_1 for the evaluation
    }
    if (s.u) {
      detail::axpy(*s.u, *s.u, half, *s.dudt, n);
      detail::copy(uhalf_, *s.u, n);
      detail::axpy(*s.u, uhalf_, half, *s.dudt, n);
    }
    eval();
    for (int k = 0; k < s.dim; ++k) detail::axpy(*s.v[k], vhalf_[k], half, *s.a[k], n);  // kick
    if (s.u) detail::axpy(*s.u, uhalf_, half, *s.dudt, n);
    return true;
  }

 private:
  std::array<std::vector<double>, 3> vhalf_;
  std::vector<double> uhalf_;
};

std::unique_ptr<Integrator> make_leapfrog() { return std::make_unique<LeapfrogIntegrator>(); }

}  // namespace sph
