// Modified Euler predictor-corrector of seed 001 eqs. 56–59 (Monaghan's scheme): one evaluation per step.
//   predictor (57): v_{i/2} = v_i + dt/2 (dv/dt)_{i-1/2},  x_{i/2} = x_i + dt/2 v_i,  u_{i/2} likewise
//   corrector (58): v_{i+1/2} = v_i + dt/2 (dv/dt)_{i/2},  x_{i+1/2} = x_i + dt/2 v_{i+1/2}
//   update   (59): y_{i+1} = 2 y_{i+1/2} - y_i   (the printed eq. 59 swaps x and v; this is the intent)
#include "phase_ops.h"

namespace sph {

class PredictorCorrector final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    const std::size_t n = s.n;
    if (!have_rates_ || rate_n_ != n) {  // first step: rates at the current state
      if (!current) eval();
      store_rates(s);
    }
    detail::save(s, y0_);
    const double half = 0.5 * dt;
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], y0_.v[k], half, a_[k], n);   // eq. 57
      detail::axpy(*s.x[k], y0_.x[k], half, y0_.v[k], n);
    }
    if (s.u) detail::axpy(*s.u, y0_.u, half, dudt_, n);
    eval();
    store_rates(s);
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], y0_.v[k], half, a_[k], n);   // eq. 58
      detail::axpy(*s.x[k], y0_.x[k], half, *s.v[k], n);
      for (std::size_t i = 0; i < n; ++i) {             // eq. 59
        (*s.v[k])[i] = 2.0 * (*s.v[k])[i] - y0_.v[k][i];
        (*s.x[k])[i] = 2.0 * (*s.x[k])[i] - y0_.x[k][i];
      }
    }
    if (s.u) {
      detail::axpy(*s.u, y0_.u, half, dudt_, n);
      for (std::size_t i = 0; i < n; ++i) (*s.u)[i] = 2.0 * (*s.u)[i] - y0_.u[i];
    }
    return false;
  }
  void reset() override { have_rates_ = false; }

 private:
  void store_rates(const PhaseSpace& s) {
    for (int k = 0; k < s.dim; ++k) detail::copy(a_[k], *s.a[k], s.n);
    if (s.u) detail::copy(dudt_, *s.dudt, s.n);
    have_rates_ = true;
    rate_n_ = s.n;
  }
  bool have_rates_ = false;
  std::size_t rate_n_ = 0;
  detail::Saved y0_;
  std::array<std::vector<double>, 3> a_;
  std::vector<double> dudt_;
};

std::unique_ptr<Integrator> make_predictor_corrector() { return std::make_unique<PredictorCorrector>(); }

}  // namespace sph
