// L1 = mean over the particles with x in the window of |f - f_exact| for f = rho, v, P, u, and the max
// norm of rho; the exact Riemann solution (reference/riemann.cpp) sampled for the profile plots.
// The star state (p*, u*, Toro §4.2) as the particles have it: the median P and v of the particles at
// least 4 h inside the exact star region (where P = p* and v = u* exactly) and 4 h away from the contact,
// with its error |p/p* - 1| and |u - u*| / s, s = |u*|, or the largest sound speed c_max when
// |u*| < 0.05 c_max (Toro's "123" has u* = 0). There, the star region is a near vacuum a few h wide,
// so instead the smallest density is compared with the exact one at the particles' positions.
// The tube ends are mirror walls: a state moving away from (or into) a wall launches a wave from it at
// t = 0, and the fan itself reaches the walls later. Each wall's wave is the Riemann problem of the
// state against its mirror image; its front moves at that problem's outermost speed. The norms are
// taken over [lo + s_lo t, hi + s_hi t], the part of the tube no wall wave has reached, and the
// comparison applies until a wall wave meets the fan (valid_until()).
#include "riemann_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "reference/compared_columns.h"
#include "sph/config.h"

namespace sph::scenes {
namespace {

class RiemannReference final : public Reference {
 public:
  RiemannReference(GasState l, GasState r, double gamma, double x0, double lo, double hi)
      : solver_(l, r, gamma, x0), x0_(x0), lo_(lo), hi_(hi),
        c_max_(std::max(std::sqrt(gamma * l.p / l.rho), std::sqrt(gamma * r.p / r.rho))) {
    s_lo_ = l.v == 0.0 ? 0.0 : std::max(0.0, wall_wave({l.rho, -l.v, l.p}, l, gamma, true));
    s_hi_ = r.v == 0.0 ? 0.0 : std::min(0.0, wall_wave(r, {r.rho, -r.v, r.p}, gamma, false));
    const WaveSpan fan = solver_.span();
    const double close_lo = s_lo_ - fan.s_min, close_hi = fan.s_max - s_hi_;  // closing speeds
    const double inf = std::numeric_limits<double>::infinity();
    valid_until_ = std::min(close_lo > 0.0 ? (x0 - lo) / close_lo : inf, close_hi > 0.0 ? (hi - x0) / close_hi : inf);
  }

  /// Speed of the wave a wall launches into the gas: the right edge of mirror | state (left wall) or the
  /// left edge of state | mirror (right wall). Two fans that would leave a vacuum: the rarefaction head.
  static double wall_wave(GasState a, GasState b, double gamma, bool left_wall) {
    try {
      const WaveSpan w = RiemannSolver(a, b, gamma).span();
      return left_wall ? w.s_max : w.s_min;
    } catch (const std::invalid_argument&) {
      const GasState& gas = left_wall ? b : a;
      const double c = std::sqrt(gamma * gas.p / gas.rho);
      return left_wall ? gas.v + c : gas.v - c;
    }
  }

  double valid_until() const override { return valid_until_; }

  std::vector<RefColumn> columns() const override {
    std::vector<RefColumn> c = {{"count", "particles compared (x inside the tube, outside the walls' own waves)", false}};
    const std::pair<const char*, const char*> l1[] = {{"rho", "rho"}, {"v", "v"}, {"p", "P"}, {"u", "u"}};
    for (const auto& [key, f] : l1)  // L1 of f = rho, v, P, u: the column's key, the field's symbol
      c.push_back({std::string("L1_") + key, std::string("mean |") + f + " - " + f + "_exact|", true});
    append_columns(c, {{"Linf_rho", "max |rho - rho_exact|", true},
                       {"p_star", "median P of the particles in the star region (NaN before it is 8 h wide)", false},
                       {"p_star_exact", "exact star pressure p*", false},
                       {"p_star_err", "|p_star / p* - 1|", true},
                       {"u_star", "median v of the particles in the star region", false},
                       {"u_star_exact", "exact star velocity u*", false},
                       {"u_star_err", "|u_star - u*| / |u*| (or / c_max where |u*| < 0.05 c_max)", true}});
    append_columns(c, compared_columns("rho_min", "smallest particle density inside the waves' fan (NaN before it holds a particle)",
                                       "smallest exact density at those particles' positions", {},
                                       ": the near-vacuum error of two rarefactions (Toro's \"123\"); NaN for other wave patterns"));
    return c;
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    double count = 0, l1r = 0, l1v = 0, l1p = 0, l1u = 0, linf = 0;
    double rmin = std::numeric_limits<double>::infinity(), rmin_exact = rmin;
    const GasState L0 = solver_.sample(-1e300, 0.0), R0 = solver_.sample(1e300, 0.0);
    auto same = [](const GasState& a, const GasState& b) {
      return a.rho == b.rho && a.v == b.v && a.p == b.p;
    };
    auto in_fan = [&](const GasState& s) { return !same(s, L0) && !same(s, R0); };
    const bool hp = p.has(Field::Pressure), hu = p.has(Field::Energy), hr = p.has(Field::Density);
    const double lo = lo_ + s_lo_ * t, hi = hi_ + s_hi_ * t;  // no wall wave inside
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      const double x = p.x[0][i];
      if (x < lo || x > hi) continue;
      const GasState s = solver_.sample(x, t);
      const double drho = hr ? std::abs(p[Field::Density][i] - s.rho) : 0.0;
      l1r += drho;
      l1v += std::abs(p.v[0][i] - s.v);
      if (hp) l1p += std::abs(p[Field::Pressure][i] - s.p);
      if (hu) l1u += std::abs(p[Field::Energy][i] - solver_.internal_energy(x, t));
      linf = std::max(linf, drho);
      if (in_fan(s)) {  // the waves' fan: a wall's own rarefaction stays out of the minimum
        if (hr) rmin = std::min(rmin, p[Field::Density][i]);
        rmin_exact = std::min(rmin_exact, s.rho);
      }
      ++count;
    }
    if (count > 0) { l1r /= count; l1v /= count; l1p /= count; l1u /= count; }
    std::vector<double> out{count, l1r, l1v, l1p, l1u, linf};
    const RiemannStar star = solver_.star();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double ps = nan, us = nan;
    if (hp && t > 0.0) {
      auto in_star = [&](double x) {
        const GasState s = solver_.sample(x, t);
        return std::abs(s.p - star.p) <= 1e-9 * star.p && std::abs(s.v - star.v) <= 1e-9 * (std::abs(star.v) + c_max_);
      };
      const double contact = x0_ + star.v * t;
      std::vector<double> pv, vv;
      for (std::size_t i = 0; i < p.fluid(); ++i) {
        const double x = p.x[0][i], m = 4.0 * p[Field::H][i];
        if (x < lo || x > hi || std::abs(x - contact) < m) continue;
        if (!in_star(x - m) || !in_star(x + m) || !in_star(x)) continue;
        pv.push_back(p[Field::Pressure][i]);
        vv.push_back(p.v[0][i]);
      }
      auto median = [](std::vector<double>& v) {
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
      };
      if (!pv.empty()) { ps = median(pv); us = median(vv); }
    }
    const double uscale = std::abs(star.v) >= 0.05 * c_max_ ? std::abs(star.v) : c_max_;
    out.insert(out.end(), {ps, star.p, relative_error(ps, star.p), us, star.v, std::abs(us - star.v) / uscale});
    // only for two rarefactions (no shock, and the contact carries no density jump when the states are
    // symmetric, as in "123"): elsewhere the minimum would measure the smearing of a jump
    const bool two_rarefactions = star.p < L0.p && star.p < R0.p;
    if (!hr || !two_rarefactions || !std::isfinite(rmin)) rmin = rmin_exact = nan;
    out.insert(out.end(), {rmin, rmin_exact, relative_error(rmin, rmin_exact)});
    return out;
  }

  std::string description() const override {
    char buf[320];
    if (s_lo_ == 0.0 && s_hi_ == 0.0)
      std::snprintf(buf, sizeof buf, "L1 = mean over particles with x in [%g, %g] of |f - f_exact|; exact Riemann solution",
                    lo_, hi_);
    else
      std::snprintf(buf, sizeof buf,
                    "L1 = mean over particles with x in [%g + %.4g t, %g + %.4g t] (outside the waves the walls launch) "
                    "of |f - f_exact|; exact Riemann solution",
                    lo_, s_lo_, hi_, s_hi_);
    std::string out = buf;
    if (std::isfinite(valid_until_)) {
      std::snprintf(buf, sizeof buf, "; it applies until t = %.4g, when a wave reaches a wall", valid_until_);
      out += buf;
    }
    return out;
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
  double x0_, lo_, hi_, c_max_;
  double s_lo_ = 0.0, s_hi_ = 0.0;  ///< speeds of the fronts of the walls' own waves (0: none)
  double valid_until_ = 0.0;        ///< when a wall's wave (or the wall) meets the fan
};

}  // namespace

std::unique_ptr<Reference> make_riemann_reference(GasState left, GasState right, double gamma, double x0, double lo,
                                                  double hi) {
  try {
    return std::make_unique<RiemannReference>(left, right, gamma, x0, lo, hi);
  } catch (const std::invalid_argument& e) {  // states the exact solver does not cover: the scene's values
    throw ConfigError(std::string("the states scene.rho_l, v_l, p_l | rho_r, v_r, p_r have no exact Riemann solution (") +
                      e.what() + "): the two rarefactions of v_r - v_l >= 2 (c_l + c_r) / (gamma - 1) leave a vacuum");
  }
}

}  // namespace sph::scenes
