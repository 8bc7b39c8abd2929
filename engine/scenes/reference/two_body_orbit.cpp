#include "reference/two_body_orbit.h"

#include <algorithm>
#include <cmath>

namespace sph::scenes {
namespace {

struct State {
  Vec3 r, v;
};

State rate(const State& s, double mu) {
  const double rn = s.r.norm();
  return {s.v, s.r * (-mu / (rn * rn * rn))};
}

State axpy(const State& s, const State& d, double h) { return {s.r + d.r * h, s.v + d.v * h}; }

}  // namespace

TwoBodyOrbit::TwoBodyOrbit(Vec3 r0, Vec3 v0, double mu, double t_max, double r_min) {
  State s{r0, v0};
  double t = 0.0;
  auto record = [&] {
    t_.push_back(t);
    r_.push_back(s.r.norm());
    dr_.push_back(s.r.dot(s.v) / s.r.norm());
  };
  record();
  constexpr int kMaxSteps = 2000000;
  for (int k = 0; k < kMaxSteps && t < t_max && r_.back() > r_min; ++k) {
    const double rn = s.r.norm();
    const double h = std::min(1e-3 * std::sqrt(rn * rn * rn / mu), t_max - t);
    const State k1 = rate(s, mu), k2 = rate(axpy(s, k1, 0.5 * h), mu), k3 = rate(axpy(s, k2, 0.5 * h), mu),
                k4 = rate(axpy(s, k3, h), mu);
    s.r += (k1.r + k2.r * 2.0 + k3.r * 2.0 + k4.r) * (h / 6.0);
    s.v += (k1.v + k2.v * 2.0 + k3.v * 2.0 + k4.v) * (h / 6.0);
    t += h;
    record();
  }
}

double TwoBodyOrbit::separation(double t) const {
  if (t < 0.0 || t > t_.back()) return std::nan("");
  const auto k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  if (k >= t_.size()) return r_.back();
  // cubic Hermite with the exact dr/dt at both ends: O(h^4), as accurate as the RK4 steps
  const double h = t_[k] - t_[k - 1], s = (t - t_[k - 1]) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * r_[k - 1] + (s3 - 2 * s2 + s) * h * dr_[k - 1] + (-2 * s3 + 3 * s2) * r_[k] +
         (s3 - s2) * h * dr_[k];
}

double TwoBodyOrbit::time_to(double r) const {
  if (r_[0] <= r) return 0.0;
  for (std::size_t k = 1; k < r_.size(); ++k)
    if (r_[k] <= r && r_[k - 1] > r) return t_[k - 1] + (r_[k - 1] - r) / (r_[k - 1] - r_[k]) * (t_[k] - t_[k - 1]);
  return std::nan("");
}

}  // namespace sph::scenes
