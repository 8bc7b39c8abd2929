// Modified Euler predictor-corrector of seed 001 eqs. 56–59 (Monaghan's scheme): one evaluation per step.
//   predictor (57): v_{i/2} = v_i + dt/2 (dv/dt)_{i-1/2},  x_{i/2} = x_i + dt/2 v_i,  rho, u likewise
//   corrector (58): v_{i+1/2} = v_i + dt/2 (dv/dt)_{i/2},  x_{i+1/2} = x_i + dt/2 v_{i+1/2}
//   update   (59): y_{i+1} = 2 y_{i+1/2} - y_i   (the printed eq. 59 swaps x and v; this is the intent)
// The rates of the predictor are those of the last evaluation (at the previous step's midpoint). With
// XSPH, dx/dt = v + the correction of the last evaluation.
#include "phase_ops.h"

namespace sph {

class PredictorCorrector final : public Integrator {
 public:
  bool step(PhaseSpace& s, const Evaluate& eval, double dt, bool current) override {
    const std::size_t n = s.n;
    if (!have_rates_ || rate_n_ != n || rates_.size() != s.evolved.size()) {  // first step: current rates
      if (!current) eval(0.0);
      store_rates(s);
    }
    detail::save(s, y0_);
    const double half = 0.5 * dt;
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], y0_.v[k], half, a_[k], n);  // eq. 57
      if (s.drifts()) detail::axpy2(*s.x[k], y0_.x[k], half, y0_.v[k], drift_[k], n);
      else detail::axpy(*s.x[k], y0_.x[k], half, y0_.v[k], n);
    }
    for (std::size_t e = 0; e < s.evolved.size(); ++e) detail::axpy(*s.evolved[e].y, y0_.y[e], half, rates_[e], n);
    eval(half);
    store_rates(s);
    for (int k = 0; k < s.dim; ++k) {
      detail::axpy(*s.v[k], y0_.v[k], half, a_[k], n);  // eq. 58
      detail::drift(s, k, *s.x[k], y0_.x[k], half, *s.v[k]);
      for (std::size_t i = 0; i < n; ++i) {  // eq. 59
        (*s.v[k])[i] = 2.0 * (*s.v[k])[i] - y0_.v[k][i];
        (*s.x[k])[i] = 2.0 * (*s.x[k])[i] - y0_.x[k][i];
      }
    }
    for (std::size_t e = 0; e < s.evolved.size(); ++e) {
      auto& y = *s.evolved[e].y;
      detail::axpy(y, y0_.y[e], half, rates_[e], n);
      for (std::size_t i = 0; i < n; ++i) y[i] = 2.0 * y[i] - y0_.y[e][i];
    }
    return false;
  }
  void reset() override { have_rates_ = false; }
  void permute(std::span<const std::uint32_t> order) override {
    if (!have_rates_ || order.size() < rate_n_) return;
    std::vector<double> copy;
    auto apply = [&](std::vector<double>& a) {
      if (a.size() < rate_n_) return;
      copy.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(rate_n_));
      for (std::size_t k = 0; k < rate_n_; ++k) a[k] = copy[order[k]];
    };
    for (auto& a : a_) apply(a);
    for (auto& d : drift_) apply(d);
    for (auto& r : rates_) apply(r);
  }
  // [rate_n], a_x, a_y, a_z, drift_x, drift_y, drift_z, then the evolved rates (nothing before a step)
  std::vector<std::vector<double>> history() const override {
    if (!have_rates_) return {};
    std::vector<std::vector<double>> h{{static_cast<double>(rate_n_)}};
    for (const auto& a : a_) h.push_back(a);
    for (const auto& d : drift_) h.push_back(d);
    for (const auto& r : rates_) h.push_back(r);
    return h;
  }
  bool set_history(const std::vector<std::vector<double>>& h) override {
    if (h.empty()) {
      have_rates_ = false;
      return true;
    }
    if (h.size() < 7 || h[0].size() != 1) return false;
    rate_n_ = static_cast<std::size_t>(h[0][0]);
    for (int k = 0; k < 3; ++k) {
      a_[k] = h[1 + k];
      drift_[k] = h[4 + k];
    }
    rates_.assign(h.begin() + 7, h.end());
    have_rates_ = true;
    return true;
  }

 private:
  void store_rates(const PhaseSpace& s) {
    for (int k = 0; k < s.dim; ++k) {
      detail::copy(a_[k], *s.a[k], s.n);
      if (s.drifts()) detail::copy(drift_[k], *s.drift[k], s.n);
    }
    rates_.resize(s.evolved.size());
    for (std::size_t e = 0; e < s.evolved.size(); ++e) detail::copy(rates_[e], *s.evolved[e].rate, s.n);
    have_rates_ = true;
    rate_n_ = s.n;
  }
  bool have_rates_ = false;
  std::size_t rate_n_ = 0;
  detail::Saved y0_;
  std::array<std::vector<double>, 3> a_, drift_;
  std::vector<std::vector<double>> rates_;
};

std::unique_ptr<Integrator> make_predictor_corrector() { return std::make_unique<PredictorCorrector>(); }

}  // namespace sph
