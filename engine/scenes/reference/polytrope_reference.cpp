#include "reference/polytrope_reference.h"

#include <algorithm>
#include <cmath>

#include "reference/compared_columns.h"
#include "reference/lane_emden.h"

namespace sph::scenes {
namespace {

constexpr int kShells = 8;

class PolytropeReference final : public Reference {
 public:
  PolytropeReference(const Params& prm, double M)
      : star_(1.0 / (prm.gas.gamma - 1.0), M, prm.gas.K, prm.gravity.G) {}
  std::vector<RefColumn> columns() const override {
    return {{"R", "Lane-Emden radius alpha xi_1 [length]", false},
            {"profile_err", "largest |<rho>/<rho_LE> - 1| over 8 shells inside 0.8 R about the centre of mass", true},
            {"virial", "3 sum m P/rho / |W|, W = 1/2 sum m phi (seed 003 eq. 3.79: 1 in equilibrium)", false},
            {"virial_err", "|virial - 1|", true}};
  }
  std::vector<double> evaluate(const Particles& p, double) const override {
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    Vec3 c;
    double M = 0.0;
    for (std::size_t i = 0; i < n; ++i) { c += p.pos(i) * m[i]; M += m[i]; }
    c = c * (1.0 / M);
    double sum[kShells] = {}, sum_le[kShells] = {};
    const bool hydro = p.has(Field::Density) && p.has(Field::Pressure), grav = p.has(Field::Potential);
    double thermal = 0.0, W = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = (p.pos(i) - c).norm();
      if (hydro) thermal += 3.0 * m[i] * p[Field::Pressure][i] / p[Field::Density][i];
      if (grav) W += 0.5 * m[i] * p[Field::Potential][i];
      const int k = static_cast<int>(r / (0.8 * star_.scales.R) * kShells);
      if (k >= kShells || !hydro) continue;
      sum[k] += p[Field::Density][i];
      sum_le[k] += star_.density(r);
    }
    double worst = 0.0;
    for (int k = 0; k < kShells; ++k)
      if (sum_le[k] > 0.0) worst = std::max(worst, relative_error(sum[k], sum_le[k]));
    const double virial = W != 0.0 ? thermal / std::abs(W) : std::nan("");
    return {star_.scales.R, hydro ? worst : std::nan(""), virial, std::abs(virial - 1.0)};
  }
  std::string description() const override {
    return "polytrope: SPH density in 8 shells inside 0.8 R against the Lane-Emden profile (seed 003 eqs. 3.72-3.78), "
           "and the virial ratio 3 sum m P/rho / |W| (eq. 3.79)";
  }
  int primary() const override { return 1; }
  /// The Lane-Emden density against r (the profile view "r" draws it over the particles).
  ReferenceCurves curves(const Domain&, double) const override {
    ReferenceCurves c;
    ExactCurve e;
    e.field = "rho";
    e.axis = 3;  // the distance from the origin
    for (int k = 0; k <= 200; ++k) {
      const double r = star_.scales.R * k / 200.0;
      e.x.push_back(static_cast<float>(r));
      e.value.push_back(static_cast<float>(star_.density(r)));
    }
    c.profiles.push_back(std::move(e));
    return c;
  }

 private:
  Polytrope star_;
};

}  // namespace

std::unique_ptr<Reference> make_polytrope_reference(const Params& prm, double M) {
  return std::make_unique<PolytropeReference>(prm, M);
}

}  // namespace sph::scenes
