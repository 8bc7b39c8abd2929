// Classical fourth-order Runge-Kutta (seed 000 App. A, eqs. A.1.1–A.1.6): four evaluations per step.
#include "phase_ops.h"

namespace sph {

class RK4Integrator final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    detail::save(s, y0_);
    const std::size_t n = s.n;
    for (int k = 0; k < s.dim; ++k) { kx_[k].assign(n, 0.0); kv_[k].assign(n, 0.0); }
    if (s.u) ku_.assign(n, 0.0);
    // stage weights b = 1/6, 1/3, 1/3, 1/6; stage offsets c = 0, 1/2, 1/2, 1
    const double b[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
    const double c[4] = {0.0, 0.5, 0.5, 1.0};
    for (int stage = 0; stage < 4; ++stage) {
      if (stage > 0 || !current) eval();
      // accumulate this stage's slopes: k_x = v, k_v = a, k_u = du/dt
      for (int k = 0; k < s.dim; ++k) {
        auto &kx = kx_[k], &kv = kv_[k];
        const auto &v = *s.v[k], &a = *s.a[k];
        for (std::size_t i = 0; i < n; ++i) { kx[i] += b[stage] * v[i]; kv[i] += b[stage] * a[i]; }
      }
      if (s.u) for (std::size_t i = 0; i < n; ++i) ku_[i] += b[stage] * (*s.dudt)[i];
      if (stage == 3) break;
      // next stage state y0 + c dt k_stage (slopes of this stage are the current v, a, du/dt)
      const double cn = c[stage + 1] * dt;
      for (int k = 0; k < s.dim; ++k) {
        detail::copy(vstage_, *s.v[k], n);  // this stage's dx/dt
        detail::axpy(*s.v[k], y0_.v[k], cn, *s.a[k], n);
        detail::axpy(*s.x[k], y0_.x[k], cn, vstage_, n);
      }
      if (s.u) detail::axpy(*s.u, y0_.u, cn, *s.dudt, n);
    }
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.x[k], y0_.x[k], dt, kx_[k], n);
      detail::axpy(*s.v[k], y0_.v[k], dt, kv_[k], n);
    }
    if (s.u) detail::axpy(*s.u, y0_.u, dt, ku_, n);
    return false;
  }

 private:
  detail::Saved y0_;
  std::array<std::vector<double>, 3> kx_, kv_;
  std::vector<double> ku_, vstage_;
};

std::unique_ptr<Integrator> make_rk4() { return std::make_unique<RK4Integrator>(); }

}  // namespace sph
