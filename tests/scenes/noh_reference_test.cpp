// The Noh reference measuring particles that carry the exact state (no error) or a centre with a
// density deficit and excess u (wall heating).
#include "reference/noh_reference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sph::scenes {
namespace {

Particles exact_noh(const Noh& noh, double t, double dx) {
  const auto n = static_cast<std::size_t>(std::llround(0.8 / dx));
  Particles p(2, n * n, FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::Energy));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = j * n + i;
      p.x[0][k] = -0.4 + (i + 0.5) * dx;
      p.x[1][k] = -0.4 + (j + 0.5) * dx;
      const NohState q = noh.state(p.pos(k).norm(), t);
      p[Field::Mass][k] = q.rho * dx * dx;
      p[Field::Density][k] = q.rho;
      p[Field::Energy][k] = q.u;
    }
  return p;
}

TEST(NohReference, MeasuresTheExactStateAsExactAndSeesWallHeating) {
  NohSetup s;
  s.margin = 0.01;
  s.dr = 0.001;
  s.r_max = 0.4;
  const auto ref = make_noh_reference(s);
  const auto cols = ref->columns();
  const double t = 0.6;
  Particles p = exact_noh(s.noh, t, 0.0005);
  std::vector<double> v = ref->evaluate(p, t);
  EXPECT_NEAR(v[find_column(cols, "rho_post")], 16.0, 1e-12);
  EXPECT_LT(v[find_column(cols, "rho_post_err")], 1e-12);
  EXPECT_NEAR(v[find_column(cols, "R")], 0.2, s.dr);
  EXPECT_LT(v[find_column(cols, "R_err")], s.dr / 0.2);
  EXPECT_NEAR(v[find_column(cols, "rho_centre_deficit")], 0.0, 1e-12);
  EXPECT_NEAR(v[find_column(cols, "u_centre_excess")], 0.0, 1e-12);
  // wall heating: half the density and twice the u inside R/3
  for (std::size_t i = 0; i < p.fluid(); ++i)
    if (p.pos(i).norm() < 0.2 / 3.0) {
      p[Field::Density][i] = 8.0;
      p[Field::Energy][i] = 1.0;
    }
  v = ref->evaluate(p, t);
  EXPECT_NEAR(v[find_column(cols, "rho_centre_deficit")], 0.5, 1e-12);
  EXPECT_NEAR(v[find_column(cols, "u_centre_excess")], 1.0, 1e-12);
  EXPECT_LT(v[find_column(cols, "rho_post_err")], 1e-12);  // the post-shock band is outside R/3
}

}  // namespace
}  // namespace sph::scenes
