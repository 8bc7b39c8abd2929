// The drop reference's semi-axes measured on exact ellipses: a square lattice inside the unit circle,
// stretched to the ODE's semi-axes (a, 1/a), as the incompressible drop carries it.
#include "reference/drop_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "reference/drop_ode.h"
#include "sph/vec.h"

namespace sph::scenes {
namespace {

Particles lattice_ellipse(double dx, double a, double shift_x, double shift_y) {
  std::vector<Vec3> pts;
  const int n = static_cast<int>(std::ceil(1.0 / dx)) + 1;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const double x = i * dx, y = j * dx;
      if (x * x + y * y <= 1.0) pts.push_back(Vec3{a * x + shift_x, y / a + shift_y, 0.0});
    }
  Particles p(2, pts.size(), FieldSet{}.add(Field::Mass));
  for (std::size_t k = 0; k < pts.size(); ++k) {
    p.x[0][k] = pts[k].x;
    p.x[1][k] = pts[k].y;
    p[Field::Mass][k] = 1000.0 * dx * dx;
  }
  return p;
}

double fitted_error(double dx, double shift_x = 0.0, double shift_y = 0.0) {
  const double t = 0.0076;
  const auto ref = make_drop_reference(100.0);
  const Particles p = lattice_ellipse(dx, drop_ode(100.0, t).a, shift_x, shift_y);
  return ref->evaluate(p, t)[static_cast<std::size_t>(find_column(ref->columns(), "err_major_fit"))];
}

TEST(DropReference, FitsTheMajorSemiAxisOfALatticeEllipseAndConverges) {
  const double coarse = fitted_error(0.05), mid = fitted_error(0.025), fine = fitted_error(0.0125);
  std::printf("err_major_fit at dx 0.05, 0.025, 0.0125: %.3g %.3g %.3g\n", coarse, mid, fine);
  EXPECT_LT(mid, 1e-3);  // the lattice's jagged rim is all that differs from the ellipse
  EXPECT_LT(fine, mid);
  EXPECT_LT(mid, coarse);
}

TEST(DropReference, TheFitIsMeasuredAboutTheCentreOfMass) {
  EXPECT_NEAR(fitted_error(0.025, 0.3, -0.2), fitted_error(0.025), 1e-9);
}

}  // namespace
}  // namespace sph::scenes
