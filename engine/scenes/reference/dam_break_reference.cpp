// The surge front Z = (largest fluid x) + dx/2 (a particle's half width: Z = a at t = 0), in units of the
// column width a, against T = t sqrt(2 g / a) and the measured fronts (dam_break_data.h), with their
// relative errors where the data cover T; the measured front drawn as a line on the floor.
#include "dam_break_reference.h"

#include <algorithm>
#include <cmath>

#include "dam_break_data.h"
#include "reference/compared_columns.h"

namespace sph::scenes {
namespace {

class DamBreakReference final : public Reference {
 public:
  DamBreakReference(double a, double dx, double g) : a_(a), dx_(dx), g_(g) {}

  std::vector<RefColumn> columns() const override {
    return {{"T", "t sqrt(2 g / a) [dimensionless]", false},
            {"front", "surge front Z/a of the particles (foremost centre + dx/2)", false},
            {"front_mm", "Martin & Moyce (1952), measured Z/a (nan outside their T range)", false},
            {"front_ko", "Koshizuka & Oka (1996), measured Z/a (nan outside their T range)", false},
            {"err_mm", "|Z/Z_mm - 1|", true},
            {"err_ko", "|Z/Z_ko - 1|", true},
            {"err_data", "|Z/Z_m - 1| for the measurement Z_m (of the two) nearer to Z: the sets differ by up to 7%",
             true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    double xmax = -1e300;
    for (std::size_t i = 0; i < p.fluid(); ++i) xmax = std::max(xmax, p.x[0][i]);
    const double T = t * std::sqrt(2.0 * g_ / a_);
    const double Z = (xmax + 0.5 * dx_) / a_;
    const double mm = interpolate_front(martin_moyce_front(), T), ko = interpolate_front(koshizuka_oka_front(), T);
    const double e_mm = relative_error(Z, mm), e_ko = relative_error(Z, ko);
    const double e = std::isnan(e_mm) ? e_ko : std::isnan(e_ko) ? e_mm : std::min(e_mm, e_ko);
    return {T, Z, mm, ko, e_mm, e_ko, e};
  }

  std::string description() const override {
    return "dam break: surge front Z/a = (foremost fluid x + dx/2)/a against T = t sqrt(2g/a) and the measured "
           "fronts of Martin & Moyce 1952 (Fig. 3, n^2 = 2) and Koshizuka & Oka 1996";
  }
  int primary() const override { return 6; }
  std::vector<std::pair<int, int>> series() const override { return {{1, 2}, {1, 3}}; }

  ReferenceCurves curves(const Domain&, double t) const override {
    ReferenceCurves c;
    const double T = t * std::sqrt(2.0 * g_ / a_);
    const double ko = interpolate_front(koshizuka_oka_front(), T), mm = interpolate_front(martin_moyce_front(), T);
    auto mark = [&](const char* label, double Z) {
      if (!std::isfinite(Z)) return;
      Outline o;
      o.label = label;
      o.x = {static_cast<float>(Z * a_), static_cast<float>(Z * a_)};
      o.y = {0.0f, static_cast<float>(0.25 * a_)};
      c.outlines.push_back(std::move(o));
    };
    mark("front, Koshizuka & Oka", ko);
    mark("front, Martin & Moyce", mm);
    return c;
  }

 private:
  double a_, dx_, g_;
};

}  // namespace

std::unique_ptr<Reference> make_dam_break_reference(double a, double dx, double g) {
  return std::make_unique<DamBreakReference>(a, dx, g);
}

}  // namespace sph::scenes
