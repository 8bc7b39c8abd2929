// Semi-axes of the drop from its particles, as PySPH measures them: the minor a = max |x| and the major
// b = max |y| over the fluid particles (their extent), the product ab (seed 001 Fig. 1b: 1 for an
// incompressible drop) and their errors against the ODE (drop_ode.h); the exact ellipse for 2D views.
// The extent jumps as the outermost particle changes, so the semi-axes are also fitted from the
// second moments: a filled ellipse has <x^2> = a^2/4 about its centre, and N particles that each stand
// for a cell of the drop's area pi/N (pi: a circle of radius 1, kept by incompressibility) add
// (pi/N)/12 of their cell's own moment: a = 2 sqrt(<x^2> + pi/(12 N)), mass-weighted.
#include "drop_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

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
            {"err_ab", "|ab - 1|", true},
            {"minor_fit", "minor semi-axis from the second moment, 2 sqrt(<x^2> + cell/12) [length]", false},
            {"major_fit", "major semi-axis from the second moment, 2 sqrt(<y^2> + cell/12) [length]", false},
            {"err_major_fit", "|b_fit / b_exact - 1|", true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      a = std::max(a, std::abs(p.x[0][i]));
      b = std::max(b, std::abs(p.x[1][i]));
    }
    const DropState e = drop_ode(A0_, t);
    const double ae = e.a, be = 1.0 / e.a;
    const auto [af, bf] = fitted_axes(p);
    return {a,  ae, b, be, a * b, 1.0, relative_error(b, be), relative_error(a, ae), std::abs(a * b - 1.0),
            af, bf, relative_error(bf, be)};
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
  /// The semi-axes from the mass-weighted second moments about the centre of mass (the file's comment).
  static std::pair<double, double> fitted_axes(const Particles& p) {
    const std::size_t n = p.fluid();
    if (n == 0) return {0.0, 0.0};
    const auto& m = p[Field::Mass];
    double M = 0.0, cx = 0.0, cy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      M += m[i];
      cx += m[i] * p.x[0][i];
      cy += m[i] * p.x[1][i];
    }
    cx /= M;
    cy /= M;
    double xx = 0.0, yy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      xx += m[i] * (p.x[0][i] - cx) * (p.x[0][i] - cx);
      yy += m[i] * (p.x[1][i] - cy) * (p.x[1][i] - cy);
    }
    const double cell = std::numbers::pi / static_cast<double>(n) / 12.0;
    return {2.0 * std::sqrt(xx / M + cell), 2.0 * std::sqrt(yy / M + cell)};
  }

  double A0_;
};

}  // namespace

std::unique_ptr<Reference> make_drop_reference(double A0) { return std::make_unique<DropReference>(A0); }

}  // namespace sph::scenes
