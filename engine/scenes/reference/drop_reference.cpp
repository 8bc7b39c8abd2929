// Semi-axes of the drop from its particles, as PySPH measures them: the minor a = max |x| and the major
// b = max |y| over the fluid particles (their extent), the product ab (seed 001 Fig. 1b: 1 for an
// incompressible drop) and their errors against the ODE (drop_ode.h); the exact ellipse for 2D views.
#include "drop_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "drop_ode.h"
#include "reference/compared_columns.h"

namespace sph::scenes {
namespace {

class DropReference final : public Reference {
 public:
  explicit DropReference(double A0) : A0_(A0) {}

  std::vector<RefColumn> columns() const override {
    return {{"minor", "minor semi-axis a = max |x| of the particles [length]", false},
            {"minor_exact", "minor semi-axis a of the incompressible ODE [length]", false},
            {"major", "major semi-axis b = max |y| of the particles [length]", false},
            {"major_exact", "major semi-axis 1/a of the ODE [length]", false},
            {"ab", "product of the measured semi-axes (1 if incompressible) [length^2]", false},
            {"ab_exact", "the exact product, 1 [length^2]", false},
            {"err_major", "|b / b_exact - 1|", true},
            {"err_minor", "|a / a_exact - 1|", true},
            {"err_ab", "|ab - 1|", true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      a = std::max(a, std::abs(p.x[0][i]));
      b = std::max(b, std::abs(p.x[1][i]));
    }
    const DropState e = drop_ode(A0_, t);
    const double ae = e.a, be = 1.0 / e.a;
    return {a, ae, b, be, a * b, 1.0, relative_error(b, be), relative_error(a, ae), std::abs(a * b - 1.0)};
  }

  std::string description() const override {
    return "elliptical drop: semi-axes = extent of the particles along x and y, against the incompressible ODE "
           "dA/dt = A^2 (a^4-1)/(a^4+1), da/dt = -a A (Monaghan 1994)";
  }
  int primary() const override { return 6; }
  std::vector<std::pair<int, int>> series() const override { return {{0, 1}, {2, 3}, {4, 5}}; }

  ReferenceCurves curves(const Domain&, double t) const override {
    const DropState e = drop_ode(A0_, t);
    Outline o;
    o.label = "exact ellipse";
    const int n = 181;
    for (int k = 0; k < n; ++k) {
      const double th = 2.0 * std::numbers::pi * k / (n - 1);
      o.x.push_back(static_cast<float>(e.a * std::cos(th)));
      o.y.push_back(static_cast<float>(std::sin(th) / e.a));
    }
    ReferenceCurves c;
    c.outlines.push_back(std::move(o));
    return c;
  }

 private:
  double A0_;
};

}  // namespace

std::unique_ptr<Reference> make_drop_reference(double A0) { return std::make_unique<DropReference>(A0); }

}  // namespace sph::scenes
