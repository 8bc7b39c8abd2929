// Mode amplitude, fitted growth rate and linear theory for the Kelvin-Helmholtz scene (kh_reference.h).
#include "kh_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <numbers>
#include <utility>
#include <vector>

#include "../kh_profile.h"
#include "kh_linear.h"

namespace sph::scenes {

namespace {
constexpr double kK = 4.0 * std::numbers::pi;  // the seeded mode: two wavelengths across the box
}

double kh_theory_rate(double ramp, double gamma) {
  ShearLayer layer;
  layer.rho = [ramp](double y) { return kh::density(y, ramp); };
  layer.U = [ramp](double y) { return kh::velocity(y, ramp); };
  layer.dUdy = [ramp](double y) { return kh::velocity_slope_lower(y, ramp); };
  layer.y_lo = 0.25 - std::min(0.25, 40.0 * ramp);  // the lower interface alone: uniform beyond 10 L
  layer.y_hi = 0.25 + std::min(0.25, 40.0 * ramp);
  layer.P = kh::kPressure;
  layer.gamma = gamma;
  const KhMode m = kh_linear_mode(layer, kK, 8000);
  return m.converged ? m.s.real() : std::numeric_limits<double>::quiet_NaN();
}

double kh_mode_amplitude(const Particles& p) {
  double s = 0.0, c = 0.0, d = 0.0;
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    const double x = p.x[0][i], y = p.x[1][i] - std::floor(p.x[1][i]);
    const double dist = y < 0.5 ? std::abs(y - 0.25) : std::abs(0.75 - y);
    const double w = p[Field::Mass][i] / p[Field::Density][i] * std::exp(-kK * dist);
    s += p.v[1][i] * w * std::sin(kK * x);
    c += p.v[1][i] * w * std::cos(kK * x);
    d += w;
  }
  return d > 0.0 ? 2.0 * std::sqrt((s / d) * (s / d) + (c / d) * (c / d)) : 0.0;
}

namespace {

class KhReference final : public Reference {
 public:
  KhReference(double ramp, double gamma, double t0, double t1)
      : ramp_(ramp), t0_(t0), t1_(t1), theory_(kh_theory_rate(ramp, gamma)),
        sheet_(kh_vortex_sheet_rate(kK, kh::kRho1, kh::kRho2, kh::kU2 - kh::kU1)) {}

  std::vector<RefColumn> columns() const override {
    return {{"amplitude", "mode amplitude M of v_y at k = 4 pi (McNally et al. 2012's diagnostic) [length/time]", false},
            {"rate_fit", "least-squares slope of ln M over the evaluations in [fit_t0, min(t, fit_t1)] [1/time]", false},
            {"rate_theory", "linear growth rate of the smooth compressible profile (shooting) [1/time]", false},
            {"rate_ratio", "rate_fit / rate_theory", false},
            {"rate_err", "|rate_fit / rate_theory - 1| (pass: < 0.2)", true},
            {"rate_sheet", "the incompressible vortex sheet's k dU sqrt(rho1 rho2)/(rho1 + rho2) [1/time]", false},
            {"fit_points", "evaluations in the fit window so far", false}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    const double M = p.has(Field::Density) ? kh_mode_amplitude(p) : std::nan("");
    double rate = std::nan("");
    std::size_t npts = 0;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!history_.empty() && t < history_.back().first) history_.clear();  // a reset
      if (!history_.empty() && t == history_.back().first) history_.back().second = M;
      else history_.emplace_back(t, M);
      double st = 0, sy = 0, stt = 0, sty = 0;
      for (const auto& [ti, mi] : history_) {
        if (ti < t0_ || ti > t1_ || !(mi > 0.0)) continue;
        const double y = std::log(mi);
        st += ti; sy += y; stt += ti * ti; sty += ti * y;
        ++npts;
      }
      const double n = static_cast<double>(npts), det = n * stt - st * st;
      if (npts >= 3 && det > 0.0) rate = (n * sty - st * sy) / det;
    }
    const double ratio = rate / theory_;
    return {M, rate, theory_, ratio, std::abs(ratio - 1.0), sheet_, static_cast<double>(npts)};
  }

  std::string description() const override {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "Kelvin-Helmholtz (McNally et al. 2012, ramp L = %g): mode amplitude of v_y at k = 4 pi, its "
                  "exponential rate fitted over t in [%g, %g] against the linear rate %.4f of the smooth "
                  "compressible profile (vortex sheet: %.4f)",
                  ramp_, t0_, t1_, theory_, sheet_);
    return buf;
  }

  int primary() const override { return 4; }

  // the evaluations so far, (t, M) pairs one after the other: the fit goes on over them after a restart
  std::vector<double> saved_state() const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<double> s;
    for (const auto& [t, m] : history_) { s.push_back(t); s.push_back(m); }
    return s;
  }
  bool restore_state(const std::vector<double>& s) override {
    if (s.size() % 2 != 0) return false;
    const std::lock_guard<std::mutex> lock(mutex_);
    history_.clear();
    for (std::size_t k = 0; k < s.size(); k += 2) history_.emplace_back(s[k], s[k + 1]);
    return true;
  }

 private:
  double ramp_, t0_, t1_, theory_, sheet_;
  mutable std::mutex mutex_;  ///< the history below is the only state; evaluate() may come from two threads
  mutable std::vector<std::pair<double, double>> history_;  ///< (t, M) of the evaluations so far
};

}  // namespace

std::unique_ptr<Reference> make_kh_reference(double ramp, double gamma, double fit_t0, double fit_t1) {
  return std::make_unique<KhReference>(ramp, gamma, fit_t0, fit_t1);
}

}  // namespace sph::scenes
