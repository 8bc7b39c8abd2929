// Mid-depth pressure (mean over the fluid particles within dx of y = H/2, y the vertical axis, and more
// than 3 dx from the side walls x = 0 and x = W, and in 3D y = 0 and y = W) and the L1 error of P over all fluid particles,
// relative to the bottom pressure rho0 g H; the exact line P(y) for profile plots.
#include "hydrostatic_reference.h"

#include <cmath>
#include <string>

#include "reference/compared_columns.h"

namespace sph::scenes {
namespace {

class HydrostaticReference final : public Reference {
 public:
  HydrostaticReference(double H, double W, double dx, double rho0, double g, int up)
      : H_(H), W_(W), dx_(dx), rho0_(rho0), g_(g), up_(up) {}

  std::vector<RefColumn> columns() const override {
    std::vector<RefColumn> c =
        compared_columns("p_mid", "mean P at mid-depth y = H/2, away from the side walls [Pa]", "rho0 g H / 2 [Pa]", "err_mid");
    c.push_back({"L1_p_rel", "mean |P - rho0 g (H - y)| / (rho0 g H) over the fluid", true});
    return c;
  }

  std::vector<double> evaluate(const Particles& p, double) const override {
    if (!p.has(Field::Pressure)) return {0, 0.5 * rho0_ * g_ * H_, 1, 1};
    const auto& P = p[Field::Pressure];
    double mid = 0.0, l1 = 0.0;
    std::size_t n_mid = 0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      const double x = p.x[0][i], y = p.x[static_cast<std::size_t>(up_)][i];
      const double x2 = up_ == 2 ? p.x[1][i] : 0.5 * W_;  // 3D: the second horizontal axis (the tank is square)
      l1 += std::abs(P[i] - rho0_ * g_ * (H_ - y));
      if (std::abs(y - 0.5 * H_) < dx_ && x > 3 * dx_ && x < W_ - 3 * dx_ && x2 > 3 * dx_ && x2 < W_ - 3 * dx_) {
        mid += P[i];
        ++n_mid;
      }
    }
    const double exact = 0.5 * rho0_ * g_ * H_;
    mid = n_mid ? mid / n_mid : 0.0;
    l1 = p.fluid() ? l1 / p.fluid() / (rho0_ * g_ * H_) : 0.0;
    return {mid, exact, relative_error(mid, exact), l1};
  }

  std::string description() const override {
    const std::string up = up_ == 2 ? "z" : "y";
    return "hydrostatic tank: P against rho0 g (H - " + up + "); p_mid = mean P of the particles within dx of mid-depth";
  }
  int primary() const override { return 2; }
  std::vector<std::pair<int, int>> series() const override { return {{0, 1}}; }

  ReferenceCurves curves(const Domain&, double) const override {
    ExactCurve c{"p", {}, {}, up_};
    for (int k = 0; k <= 50; ++k) {
      const double y = H_ * k / 50.0;
      c.x.push_back(static_cast<float>(y));
      c.value.push_back(static_cast<float>(rho0_ * g_ * (H_ - y)));
    }
    ReferenceCurves r;
    r.profiles.push_back(std::move(c));
    return r;
  }

 private:
  double H_, W_, dx_, rho0_, g_;
  int up_;
};

}  // namespace

std::unique_ptr<Reference> make_hydrostatic_reference(double H, double W, double dx, double rho0, double g, int up) {
  return std::make_unique<HydrostaticReference>(H, W, dx, rho0, g, up);
}

}  // namespace sph::scenes
