// Noh's exact solution and its reference: the jump conditions (rho2 = 16, P2 = 16/3, shock at t/3 for
// gamma = 5/3 in 2D) from the Rankine-Hugoniot relations, and the reference measuring particles that
// carry the exact state (no error) or a centre with a density deficit (wall heating).
#include "reference/noh_reference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/noh_solution.h"

namespace sph::scenes {
namespace {

TEST(NohSolution, JumpConditionsHoldAtTheShock) {
  const Noh noh;  // 2D, gamma 5/3, rho0 = v0 = 1
  EXPECT_DOUBLE_EQ(noh.post_shock_density(), 16.0);
  EXPECT_DOUBLE_EQ(noh.shock_radius(0.6), 0.2);
  const double t = 0.6, R = noh.shock_radius(t), U = noh.shock_speed();
  const NohState in = noh.state(R * (1 - 1e-12), t), out = noh.state(R * (1 + 1e-12), t);
  EXPECT_NEAR(in.P, 16.0 / 3.0, 1e-12);
  EXPECT_NEAR(out.rho, 4.0, 1e-9);  // 1 + t/r at r = t/3
  // mass and momentum fluxes through the shock in its frame (Landau & Lifshitz §85)
  const double w_out = out.v - U, w_in = in.v - U;
  EXPECT_NEAR(out.rho * w_out, in.rho * w_in, 1e-9);
  EXPECT_NEAR(out.P + out.rho * w_out * w_out, in.P + in.rho * w_in * w_in, 1e-9);
  // energy flux: rho w (u + P/rho + w^2/2)
  EXPECT_NEAR(out.rho * w_out * (out.u + 0.5 * w_out * w_out), in.rho * w_in * (in.u + in.P / in.rho + 0.5 * w_in * w_in),
              1e-9);
  // 3D: rho2 = 64 (Noh 1987)
  EXPECT_DOUBLE_EQ((Noh{3, 5.0 / 3.0, 1.0, 1.0}.post_shock_density()), 64.0);
}

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
