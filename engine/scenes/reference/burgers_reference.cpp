#include "reference/burgers_reference.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "reference/burgers_exact.h"

namespace sph::scenes {
namespace {

class BurgersReference final : public Reference {
 public:
  BurgersReference(double a, double eps) : a_(a), eps_(eps) {}

  std::vector<RefColumn> columns() const override {
    std::vector<RefColumn> c{
        {"e_seed", "seed 002's e(h) = h_max sum |u - u_exact| against eq. 22 (inviscid) [length^2/time]", true},
        {"L1_u", "mean |u - u_exact| over the points, against eq. 22 [length/time]", true}};
    if (eps_ > 0.0)
      c.push_back({"e_viscous", "e(h) against the viscous solution (Cole-Hopf) at this eps [length^2/time]", true});
    return c;
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    const std::size_t n = p.fluid();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p.x[0][i] < p.x[0][j]; });
    std::vector<double> x(n), u(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = p.x[0][order[k]];
      u[k] = p.v[0][order[k]];
    }
    auto inviscid = [&](double xx) { return burgers_inviscid(xx, t, a_); };
    const double e = seed_error(x, u, inviscid);
    double l1 = 0.0;
    for (std::size_t k = 0; k < n; ++k) l1 += std::abs(u[k] - inviscid(x[k]));
    std::vector<double> out{e, n > 0 ? l1 / static_cast<double>(n) : 0.0};
    if (eps_ > 0.0) out.push_back(seed_error(x, u, [&](double xx) { return burgers_viscous(xx, t, a_, eps_); }));
    return out;
  }

  std::string description() const override {
    std::string s = "Burgers' equation from the ramp u0 (seed 002 eq. 6c, a = " + std::to_string(a_) +
                    "): e_seed = h_max sum_i |u_i - u(x_i,t)| (seed 002 §4.3) and L1_u = mean |u_i - u(x_i,t)|, u of "
                    "eq. 22 (the shock at x = a + (t - a)/2 after t = a)";
    if (eps_ > 0.0)
      s += "; e_viscous = the same sum against the viscous (Cole-Hopf) solution at eps = " + std::to_string(eps_);
    return s;
  }

  ReferenceCurves curves(const Domain& d, double t) const override {
    ReferenceCurves rc;
    ExactCurve u{"vx", {}, {}, 0};
    const int samples = 801;
    for (int k = 0; k < samples; ++k) {
      const double x = d.lo[0] + (d.hi[0] - d.lo[0]) * k / (samples - 1);
      u.x.push_back(static_cast<float>(x));
      u.value.push_back(static_cast<float>(eps_ > 0.0 ? burgers_viscous(x, t, a_, eps_) : burgers_inviscid(x, t, a_)));
    }
    rc.profiles.push_back(std::move(u));
    return rc;
  }

 private:
  double a_, eps_;
};

}  // namespace

std::unique_ptr<Reference> make_burgers_reference(double a, double eps) {
  return std::make_unique<BurgersReference>(a, eps);
}

}  // namespace sph::scenes
