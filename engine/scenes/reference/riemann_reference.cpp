// L1 = mean over the particles with x in the window of |f - f_exact| for f = rho, v, P, u, and the max
// norm of rho; the exact Riemann solution (reference/riemann.cpp) sampled for the profile plots.
#include "riemann_reference.h"

#include <algorithm>
#include <cmath>

namespace sph::scenes {
namespace {

class RiemannReference final : public Reference {
 public:
  RiemannReference(GasState l, GasState r, double gamma, double x0, double lo, double hi)
      : solver_(l, r, gamma, x0), lo_(lo), hi_(hi) {}

  std::vector<RefColumn> columns() const override {
    return {{"count", "particles compared (x inside the tube)", false},
            {"L1_rho", "mean |rho - rho_exact|", true},
            {"L1_v", "mean |v - v_exact|", true},
            {"L1_p", "mean |P - P_exact|", true},
            {"L1_u", "mean |u - u_exact|", true},
            {"Linf_rho", "max |rho - rho_exact|", true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    double count = 0, l1r = 0, l1v = 0, l1p = 0, l1u = 0, linf = 0;
    const bool hp = p.has(Field::Pressure), hu = p.has(Field::Energy), hr = p.has(Field::Density);
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      const double x = p.x[0][i];
      if (x < lo_ || x > hi_) continue;
      const GasState s = solver_.sample(x, t);
      const double drho = hr ? std::abs(p[Field::Density][i] - s.rho) : 0.0;
      l1r += drho;
      l1v += std::abs(p.v[0][i] - s.v);
      if (hp) l1p += std::abs(p[Field::Pressure][i] - s.p);
      if (hu) l1u += std::abs(p[Field::Energy][i] - solver_.internal_energy(x, t));
      linf = std::max(linf, drho);
      ++count;
    }
    if (count > 0) { l1r /= count; l1v /= count; l1p /= count; l1u /= count; }
    return {count, l1r, l1v, l1p, l1u, linf};
  }

  std::string description() const override {
    char buf[160];
    std::snprintf(buf, sizeof buf, "L1 = mean over particles with x in [%g, %g] of |f - f_exact|; exact Riemann solution",
                  lo_, hi_);
    return buf;
  }

  int primary() const override { return 1; }

  ReferenceCurves curves(const Domain& d, double t) const override {
    const int samples = 801;
    const double lo = d.lo[0], hi = d.hi[0];
    ExactCurve rho{"rho", {}, {}, 0}, pr{"p", {}, {}, 0}, u{"u", {}, {}, 0}, vx{"vx", {}, {}, 0},
        sp{"speed", {}, {}, 0};
    for (int k = 0; k < samples; ++k) {
      const double x = lo + (hi - lo) * k / (samples - 1);
      const GasState st = solver_.sample(x, t);
      for (ExactCurve* c : {&rho, &pr, &u, &vx, &sp}) c->x.push_back(static_cast<float>(x));
      rho.value.push_back(static_cast<float>(st.rho));
      pr.value.push_back(static_cast<float>(st.p));
      u.value.push_back(static_cast<float>(solver_.internal_energy(x, t)));
      vx.value.push_back(static_cast<float>(st.v));
      sp.value.push_back(static_cast<float>(std::abs(st.v)));
    }
    ReferenceCurves c;
    c.profiles = {rho, pr, u, vx, sp};
    return c;
  }

 private:
  RiemannSolver solver_;
  double lo_, hi_;
};

}  // namespace

std::unique_ptr<Reference> make_riemann_reference(GasState left, GasState right, double gamma, double x0, double lo,
                                                  double hi) {
  return std::make_unique<RiemannReference>(left, right, gamma, x0, lo, hi);
}

}  // namespace sph::scenes
