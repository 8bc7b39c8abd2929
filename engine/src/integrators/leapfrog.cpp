// Leapfrog kick-drift-kick: symplectic and time reversible for conservative forces (seed 003 §2
// recommends a symplectic Stoermer-Verlet scheme for long runs; seed 004). One evaluation per step.
// The evaluation after the drift sees the predicted v + dt/2 a_old and y + dt/2 rate_old, as usual for
// velocity-dependent SPH forces. With XSPH the drift uses v_1/2 plus the last evaluation's correction.
#include "phase_ops.h"

namespace sph {

class LeapfrogIntegrator final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    if (!current) eval(0.0);
    const std::size_t n = s.n;
    const double half = 0.5 * dt;
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], *s.v[k], half, *s.a[k], n);   // kick: v_{1/2}
      detail::drift(s, k, *s.x[k], *s.x[k], dt, *s.v[k]);  // drift: x_1
      detail::copy(vhalf_[k], *s.v[k], n);
      detail::axpy(*s.v[k], vhalf_[k], half, *s.a[k], n);  // predicted v_1 for the evaluation
    }
    yhalf_.resize(s.evolved.size());
    for (std::size_t e = 0; e < s.evolved.size(); ++e) {
      const EvolvedArray& ev = s.evolved[e];
      detail::axpy(*ev.y, *ev.y, half, *ev.rate, n);
      detail::copy(yhalf_[e], *ev.y, n);
      detail::axpy(*ev.y, yhalf_[e], half, *ev.rate, n);
    }
    eval(dt);
    for (int k = 0; k < s.dim; ++k) detail::axpy(*s.v[k], vhalf_[k], half, *s.a[k], n);  // kick
    for (std::size_t e = 0; e < s.evolved.size(); ++e)
      detail::axpy(*s.evolved[e].y, yhalf_[e], half, *s.evolved[e].rate, n);
    return true;
  }

 private:
  std::array<std::vector<double>, 3> vhalf_;
  std::vector<std::vector<double>> yhalf_;
};

std::unique_ptr<Integrator> make_leapfrog() { return std::make_unique<LeapfrogIntegrator>(); }

}  // namespace sph
