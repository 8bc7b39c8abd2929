// The Gresho vortex's reference: since the solution is stationary, the exact state at time t is the
// initial one. L1 norms are means over all N real particles of the box (the region r > 0.4 at rest
// included), L1(v_phi) = (1/N) sum_i |v_phi,i - v_phi(r_i)| with v_phi,i = (x v_y - y v_x)/r, and
// L1(P) likewise; the mean |v_r| measures the spurious radial motion.
#include "gresho_reference.h"

#include <cmath>
#include <cstdio>

namespace sph::scenes {

double gresho_vphi(double r) {
  if (r < 0.2) return 5.0 * r;
  if (r < 0.4) return 2.0 - 5.0 * r;
  return 0.0;
}

double gresho_pressure(double r) {
  if (r < 0.2) return 5.0 + 12.5 * r * r;
  if (r < 0.4) return 9.0 + 12.5 * r * r - 20.0 * r + 4.0 * std::log(5.0 * r);
  return 3.0 + 4.0 * std::log(2.0);
}

namespace {

class GreshoReference final : public Reference {
 public:
  std::vector<RefColumn> columns() const override {
    return {{"L1_vphi", "mean over all particles of |v_phi - v_phi_exact(r)| [length/time]", true},
            {"L1_p", "mean over all particles of |P - P_exact(r)| [pressure]", true},
            {"mean_abs_vr", "mean over all particles of |v_r| (exact 0) [length/time]", true},
            {"vphi_peak", "mean v_phi of the particles with 0.18 < r < 0.22 (exact ~1) [length/time]", false}};
  }

  std::vector<double> evaluate(const Particles& p, double) const override {
    const std::size_t n = p.fluid();
    const bool hp = p.has(Field::Pressure);
    double l1v = 0.0, l1p = 0.0, vr = 0.0, peak = 0.0;
    std::size_t npeak = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = p.x[0][i], y = p.x[1][i], r = std::hypot(x, y);
      const double vx = p.v[0][i], vy = p.v[1][i];
      const double vphi = r > 0.0 ? (x * vy - y * vx) / r : 0.0, vrad = r > 0.0 ? (x * vx + y * vy) / r : 0.0;
      l1v += std::abs(vphi - gresho_vphi(r));
      if (hp) l1p += std::abs(p[Field::Pressure][i] - gresho_pressure(r));
      vr += std::abs(vrad);
      if (r > 0.18 && r < 0.22) { peak += vphi; ++npeak; }
    }
    const double N = n > 0 ? static_cast<double>(n) : 1.0;
    return {l1v / N, hp ? l1p / N : std::nan(""), vr / N, npeak ? peak / static_cast<double>(npeak) : std::nan("")};
  }

  std::string description() const override {
    return "Gresho-Chan vortex, stationary: L1 = mean over all particles of |f - f_exact(r)|, r from the origin, "
           "v_phi = (x v_y - y v_x)/r";
  }

  ReferenceCurves curves(const Domain&, double) const override {
    // the speed |v| (= v_phi for the exact flow) and P against r, out to the box's corner
    ExactCurve speed{"speed", {}, {}, 3}, pr{"p", {}, {}, 3};
    const int samples = 401;
    for (int k = 0; k < samples; ++k) {
      const double r = 0.7072 * k / (samples - 1);
      speed.x.push_back(static_cast<float>(r));
      pr.x.push_back(static_cast<float>(r));
      speed.value.push_back(static_cast<float>(gresho_vphi(r)));
      pr.value.push_back(static_cast<float>(gresho_pressure(r)));
    }
    ReferenceCurves c;
    c.profiles = {speed, pr};
    return c;
  }
};

}  // namespace

std::unique_ptr<Reference> make_gresho_reference() { return std::make_unique<GreshoReference>(); }

}  // namespace sph::scenes
