// The inspector's split of a force stage (engine/src/inspect/force_terms.cpp): for two gas particles the
// pressure and viscosity terms and their du/dt are the seed's formulas evaluated by hand; on a jittered
// liquid lattice the terms of every formulation add up to the accelerations the stage itself computed.
#include <gtest/gtest.h>

#include <cmath>

#include "inspect/force_terms.h"
#include "stage_test_util.h"

namespace sph {
namespace {

const InspectTerm& term(const std::vector<InspectTerm>& terms, const std::string& name) {
  for (const InspectTerm& t : terms)
    if (t.name == name) return t;
  ADD_FAILURE() << "no term " << name;
  return terms.front();
}

TEST(ForceTerms, TwoGasParticlesByHand) {
  Params prm;
  prm.physics.density = DensityMode::Summation;  // grad-h terms
  prm.physics.force = ForceType::Standard;
  prm.physics.viscosity = ViscType::Monaghan;
  prm.physics.energy = Toggle::On;
  prm.visc.alpha = 1.0;
  prm.visc.beta = 2.0;
  prm.visc.eps = 0.01;
  test::StageBench b(prm, 1, 2, test::pipeline_fields(prm, 1));
  Particles& p = b.p;
  // a at 0 moving right, b at 0.03 moving left: approaching
  const double x[2] = {0.0, 0.03}, v[2] = {0.4, -0.2}, m[2] = {0.002, 0.003}, rho[2] = {1.0, 0.8};
  const double h[2] = {0.02, 0.025}, P[2] = {1.0, 0.6}, om[2] = {1.1, 0.95}, c[2] = {1.2, 1.0};
  for (int i = 0; i < 2; ++i) {
    p.x[0][i] = x[i];
    p.v[0][i] = v[i];
    p[Field::Mass][i] = m[i];
    p[Field::Density][i] = rho[i];
    p[Field::H][i] = h[i];
    p[Field::Pressure][i] = P[i];
    p[Field::Omega][i] = om[i];
    p[Field::SoundSpeed][i] = c[i];
  }
  b.prepare(FieldSet{}.add(Field::Density).add(Field::Pressure).add(Field::Omega).add(Field::SoundSpeed));
  std::vector<InspectTerm> terms;
  std::vector<InspectNeighbour> nb;
  EXPECT_EQ(force_terms(b.context(), 0, &terms, &nb), "standard");
  ASSERT_EQ(nb.size(), 1u);
  EXPECT_EQ(nb[0].id, 1);
  const Kernel K(KernelType::M4, 1);
  const double r = 0.03, rhat = -1.0;  // x_a - x_b = -0.03
  const double dWa = K.dWdr(r, h[0]), dWb = K.dWdr(r, h[1]), dWm = 0.5 * (dWa + dWb);
  const double Aa = P[0] / (om[0] * rho[0] * rho[0]), Ab = P[1] / (om[1] * rho[1] * rho[1]);
  // seed 000 eq. 3.3.17 and 3.3.19
  EXPECT_NEAR(term(terms, "pressure").a.x, -m[1] * (Aa * dWa + Ab * dWb) * rhat, 1e-12);
  const double w = (v[0] - v[1]) * rhat;  // v_ab . r_hat < 0: approaching
  EXPECT_NEAR(term(terms, "pressure").dudt, Aa * m[1] * w * dWa, 1e-12);
  // Monaghan Pi (seed 003 eq. 3.16)
  const double hm = 0.5 * (h[0] + h[1]), vdotr = (v[0] - v[1]) * (x[0] - x[1]);
  const double mu = hm * vdotr / (r * r + 0.01 * hm * hm);
  const double Pi = (-1.0 * 0.5 * (c[0] + c[1]) * mu + 2.0 * mu * mu) / (0.5 * (rho[0] + rho[1]));
  EXPECT_GT(Pi, 0.0);
  EXPECT_NEAR(term(terms, "artificial viscosity Pi").a.x, -m[1] * Pi * dWm * rhat, 1e-12);
  EXPECT_NEAR(term(terms, "artificial viscosity Pi").dudt, 0.5 * m[1] * Pi * w * dWm, 1e-12);
  EXPECT_GT(term(terms, "artificial viscosity Pi").dudt, 0.0);  // dissipation heats
  EXPECT_NEAR(nb[0].W, K.W(r, h[0]), 1e-12);
  EXPECT_NEAR(nb[0].share, m[1] * K.W(r, h[0]) / rho[0], 1e-12);
}

/// Runs the whole pipeline of prm on a jittered 12 x 12 lattice in a periodic box (liquid at rest with a
/// velocity field), then checks that the terms of every particle add up to the stage's acceleration.
void expect_sums_match(Params prm, const char* what) {
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  constexpr std::size_t n = 12;
  constexpr double dx = 0.1;
  test::StageBench b(prm, 2, n * n, test::pipeline_fields(prm, 2));
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {n * dx, n * dx, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  test::jittered_lattice(b.p, n, dx, 0.3, 1.3 * dx, 1000.0);
  for (std::size_t i = 0; i < n * n; ++i) {
    b.p.v[0][i] = std::sin(2.0 * b.p.x[1][i]);
    b.p.v[1][i] = 0.3 * std::cos(3.0 * b.p.x[0][i]);
    b.p[Field::Density][i] = 1000.0 * (1.0 + 0.01 * std::sin(5.0 * b.p.x[0][i]));
  }
  b.prepare(FieldSet{}.add(Field::Density));
  b.run_pipeline();
  double worst = 0.0;
  for (std::size_t i = 0; i < n * n; ++i) {
    std::vector<InspectTerm> terms;
    std::vector<InspectNeighbour> nb;
    force_terms(b.context(), i, &terms, &nb);
    Vec3 sum;
    double scale = 0.0;
    for (const InspectTerm& t : terms) sum += t.a, scale += t.a_scale;
    const Vec3 a{b.p.a[0][i], b.p.a[1][i], b.p.a[2][i]};
    ASSERT_GT(scale, 0.0);
    worst = std::max(worst, (sum - a).norm() / scale);
  }
  EXPECT_LE(worst, 1e-12) << what;
}

TEST(ForceTerms, EveryFormulationAddsUpToItsStage) {
  Params sc;
  sc.physics.force = ForceType::StandardCorrected;
  sc.physics.viscosity = ViscType::Monaghan;
  expect_sums_match(sc, "standard-corrected, Monaghan");
  sc.physics.viscosity = ViscType::Laplacian;
  expect_sums_match(sc, "standard-corrected, Laplacian");
  Params st;
  st.physics.force = ForceType::Standard;
  st.physics.viscosity = ViscType::Laplacian;
  expect_sums_match(st, "standard, Laplacian");
  Params co;
  co.physics.force = ForceType::Corrected;
  co.physics.viscosity = ViscType::Laplacian;
  co.visc.nu = 0.05;
  expect_sums_match(co, "corrected, viscous stress");
  co.physics.viscosity = ViscType::Monaghan;
  expect_sums_match(co, "corrected, Monaghan");
  // alpha per particle (the Balsara switch varies it from particle to particle): the inspector's Pi is
  // the loops' own term type, so the split still adds up
  st.physics.viscosity = ViscType::Monaghan;
  st.physics.visc_switch = ViscSwitch::Balsara;
  expect_sums_match(st, "standard, Monaghan with the Balsara switch");
  sc.physics.viscosity = ViscType::Monaghan;
  sc.physics.visc_switch = ViscSwitch::Balsara;
  expect_sums_match(sc, "standard-corrected, Monaghan with the Balsara switch");
}

}  // namespace
}  // namespace sph
