// Shell profiles and the shock-front estimator on a known step: the half-height crossing is the step.
#include "reference/radial_profile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sph::scenes {
namespace {

TEST(RadialProfile, ShellMeansAndTheFrontOfASmoothedStep) {
  // a square lattice in [-1, 1]^2 with rho = 1 + 3 s((r - 0.5)/w), s a symmetric smoothed step from 1 to 0
  const double dx = 0.002, w = 0.02;
  const auto n = static_cast<std::size_t>(std::llround(2.0 / dx));
  Particles p(2, n * n, FieldSet{}.add(Field::Density));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = j * n + i;
      p.x[0][k] = -1.0 + (i + 0.5) * dx;
      p.x[1][k] = -1.0 + (j + 0.5) * dx;
      p[Field::Density][k] = 1.0 + 3.0 * 0.5 * (1.0 - std::tanh((p.pos(k).norm() - 0.5) / w));
    }
  const RadialProfile prof = radial_profile(p, Field::Density, 0.004, 200);
  EXPECT_EQ(prof.count[0], 12u);  // the lattice points within one shell of the origin (r < 0.004)
  EXPECT_NEAR(prof.mean[10], 4.0, 1e-6);
  EXPECT_NEAR(prof.mean[199], 1.0, 1e-6);
  const Peak peak = profile_peak(prof, 3);
  EXPECT_NEAR(peak.value, 4.0, 1e-6);
  EXPECT_NEAR(shock_front(prof, 1.0), 0.5, 0.1 * prof.dr);
  // nothing denser than the gas ahead: no front
  EXPECT_EQ(shock_front(prof, 7.0), 0.0);
}

}  // namespace
}  // namespace sph::scenes
