// The blast reference on particles that carry the exact self-similar state: the shock radius it measures
// is within one shell of R(t), L1(rho) vanishes, the energy drift is read from sum m (u + v^2/2).
#include "reference/sedov_reference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reference/sedov_solution.h"
#include "sph/fields.h"

namespace sph::scenes {
namespace {

/// A square lattice of spacing dx over [-0.5, 0.5]^2 with the exact Sedov density at t.
Particles exact_blast(const SedovSolution& sol, double t, double dx, double u_each) {
  const auto n = static_cast<std::size_t>(std::llround(1.0 / dx));
  Particles p(2, n * n, FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::Energy));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = j * n + i;
      p.x[0][k] = -0.5 + (i + 0.5) * dx;
      p.x[1][k] = -0.5 + (j + 0.5) * dx;
      p[Field::Mass][k] = dx * dx;
      p[Field::Density][k] = sol.state(p.pos(k).norm(), t, 1.0, 1.0).rho;
      p[Field::Energy][k] = u_each;
    }
  return p;
}

TEST(SedovReference, MeasuresTheExactStateAsExact) {
  SedovSetup s;  // 2D, gamma 5/3, E = 1, rho1 = 1
  s.u_ambient = 1e-5 / (2.0 / 3.0);
  s.dr = 0.002;
  s.r_max = 0.5;
  const auto ref = make_sedov_reference(s);
  const SedovSolution sol(2, 5.0 / 3.0);
  const double t = 0.1, dx = 0.001;
  // u = u_ambient + E / M on every particle: sum m u = E + M u_ambient, the reference's E(0)
  const Particles p = exact_blast(sol, t, dx, s.u_ambient + 1.0);
  const auto cols = ref->columns();
  const std::vector<double> v = ref->evaluate(p, t);
  ASSERT_EQ(v.size(), cols.size());
  const double R = v[find_column(cols, "R")], R_exact = v[find_column(cols, "R_exact")];
  EXPECT_NEAR(R_exact, sol.xi0() * std::pow(t * t, 0.25), 1e-12);
  EXPECT_NEAR(R, R_exact, s.dr);  // the half-height crossing of the exact jump, within one shell
  EXPECT_LT(v[find_column(cols, "L1_rho")], 1e-12);
  EXPECT_LT(v[find_column(cols, "dE_rel")], 1e-10);  // round-off of a sum over 1e6 particles
  // the densest shell sits just behind the jump, a little below (gamma+1)/(gamma-1) = 4
  EXPECT_GT(v[find_column(cols, "rho_peak")], 3.5);
  EXPECT_LE(v[find_column(cols, "rho_peak")], 4.0);
}

TEST(SedovReference, SeesAShockTooFarOutAndAnEnergyLoss) {
  SedovSetup s;
  s.dr = 0.002;
  const auto ref = make_sedov_reference(s);
  const SedovSolution sol(2, 5.0 / 3.0);
  // the profile of t = 0.1 reported at t = 0.08: the measured radius is (0.1/0.08)^(1/2) times R_exact
  const Particles p = exact_blast(sol, 0.1, 0.001, 0.99);
  const auto cols = ref->columns();
  const std::vector<double> v = ref->evaluate(p, 0.08);
  EXPECT_NEAR(v[find_column(cols, "R_err")], std::sqrt(0.1 / 0.08) - 1.0, 0.01);
  EXPECT_GT(v[find_column(cols, "L1_rho")], 0.1);
  EXPECT_NEAR(v[find_column(cols, "dE_rel")], 0.01, 1e-9);
}

}  // namespace
}  // namespace sph::scenes
