// exp_poly against the C library's exp: within 2 ulp over the whole range the engine uses.
#include "sph/exp_poly.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

TEST(ExpPoly, WithinTwoUlpOfTheLibraryExp) {
  const double eps = std::numeric_limits<double>::epsilon();
  double worst = 0.0, at = 0.0;
  // dense on the Gaussian kernel's range [-9, 0], then the whole finite range
  for (int k = 0; k <= 200000; ++k) {
    const double x = -9.0 + 9.0 * k / 200000.0;
    const double e = std::exp(x), rel = std::abs(sph::exp_poly(x) - e) / e;
    if (rel > worst) { worst = rel; at = x; }
  }
  for (int k = 0; k <= 200000; ++k) {
    const double x = -708.0 + 1417.0 * k / 200000.0;
    const double e = std::exp(x), rel = std::abs(sph::exp_poly(x) - e) / e;
    if (rel > worst) { worst = rel; at = x; }
  }
  EXPECT_LE(worst, 2.0 * eps) << "at x = " << at;
}

TEST(ExpPoly, ExactWhereExpIsExact) {
  EXPECT_EQ(sph::exp_poly(0.0), 1.0);
  EXPECT_EQ(sph::exp_poly(-0.0), 1.0);
}

}  // namespace
