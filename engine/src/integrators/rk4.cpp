// Classical fourth-order Runge-Kutta (seed 000 App. A, eqs. A.1.1–A.1.6): four evaluations per step.
// The slope of x is dx/dt = v (+ the XSPH correction of each stage's evaluation).
#include "phase_ops.h"

namespace sph {

class RK4Integrator final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    detail::save(s, y0_);
    const std::size_t n = s.n;
    const std::size_t ne = s.evolved.size();
    for (int k = 0; k < s.dim; ++k) { kx_[k].assign(n, 0.0); kv_[k].assign(n, 0.0); }
    ky_.resize(ne);
    for (auto& k : ky_) k.assign(n, 0.0);
    // stage weights b = 1/6, 1/3, 1/3, 1/6; stage offsets c = 0, 1/2, 1/2, 1
    const double b[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
    const double c[4] = {0.0, 0.5, 0.5, 1.0};
    for (int stage = 0; stage < 4; ++stage) {
      if (stage > 0 || !current) eval(c[stage] * dt);
      // accumulate this stage's slopes: k_x = v (+ drift), k_v = a, k_y = rate
      for (int k = 0; k < s.dim; ++k) {
        auto &kx = kx_[k], &kv = kv_[k];
        const auto &v = *s.v[k], &a = *s.a[k];
        if (s.drifts()) {
          const auto& dr = *s.drift[k];
          for (std::size_t i = 0; i < n; ++i) { kx[i] += b[stage] * (v[i] + dr[i]); kv[i] += b[stage] * a[i]; }
        } else {
          for (std::size_t i = 0; i < n; ++i) { kx[i] += b[stage] * v[i]; kv[i] += b[stage] * a[i]; }
        }
      }
      for (std::size_t e = 0; e < ne; ++e) {
        const auto& rate = *s.evolved[e].rate;
        for (std::size_t i = 0; i < n; ++i) ky_[e][i] += b[stage] * rate[i];
      }
      if (stage == 3) break;
      // next stage state y0 + c dt k_stage (slopes of this stage are the current v (+ drift), a, rates)
      const double cn = c[stage + 1] * dt;
      for (int k = 0; k < s.dim; ++k) {
        detail::copy(vstage_, *s.v[k], n);  // this stage's v, before it is overwritten
        detail::axpy(*s.v[k], y0_.v[k], cn, *s.a[k], n);
        detail::drift(s, k, *s.x[k], y0_.x[k], cn, vstage_);
      }
      for (std::size_t e = 0; e < ne; ++e) detail::axpy(*s.evolved[e].y, y0_.y[e], cn, *s.evolved[e].rate, n);
    }
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.x[k], y0_.x[k], dt, kx_[k], n);
      detail::axpy(*s.v[k], y0_.v[k], dt, kv_[k], n);
    }
    for (std::size_t e = 0; e < ne; ++e) detail::axpy(*s.evolved[e].y, y0_.y[e], dt, ky_[e], n);
    return false;
  }

 private:
  detail::Saved y0_;
  std::array<std::vector<double>, 3> kx_, kv_;
  std::vector<std::vector<double>> ky_;
  std::vector<double> vstage_;
};

std::unique_ptr<Integrator> make_rk4() { return std::make_unique<RK4Integrator>(); }

}  // namespace sph
