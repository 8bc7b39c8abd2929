// The viscosity switches (visc.switch; physics/viscosity_switch.cpp, terms/visc_switch_law.h): Balsara's
// limiter in pure compression and pure shear, the Cullen-Dehnen alpha's rise, exact exponential decay and
// bounds, the stage's div v and |curl v| against sinusoidal velocity fields, and the combinations refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics/terms/visc_switch_law.h"
#include "sph/config.h"
#include "stage_test_util.h"

namespace sph {
namespace {

using terms::balsara_factor;
using terms::CullenDehnenLaw;

TEST(ViscositySwitch, BalsaraFactorIsOneInCompressionAndZeroInRotation) {
  // f = |div v| / (|div v| + |curl v| + 1e-4 c/h), c = 1, h = 0.01: the floor 1e-4 c/h = 0.01
  EXPECT_NEAR(balsara_factor(-2.0, 0.0, 1.0, 0.01), 2.0 / 2.01, 1e-15);
  EXPECT_EQ(balsara_factor(0.0, 2.0, 1.0, 0.01), 0.0);
  EXPECT_NEAR(balsara_factor(-1.0, 1.0, 1.0, 0.01), 1.0 / 2.01, 1e-15);
  EXPECT_EQ(balsara_factor(0.0, 0.0, 0.0, 0.01), 0.0);  // at rest and cold: no viscosity, no 0/0
}

TEST(ViscositySwitch, CullenDehnenAlphaRisesAtOnceInACompressionThatSteepens) {
  const CullenDehnenLaw law{0.0, 1.0, 0.1};
  // div v from -0.9 to -1 over dt = 0.01: d(div v)/dt = -10; xi = 1 (no curl); H = 0.1, c = 1:
  // H^2 A = 0.1, alpha_loc = 0.1 / 1.1
  EXPECT_NEAR(law.local(-1.0, -0.9, 0.0, 0.01, 1.0, 0.1), 0.1 / 1.1, 1e-14);
  EXPECT_NEAR(law.next(0.0, -1.0, -0.9, 0.0, 0.01, 1.0, 0.1), 0.1 / 1.1, 1e-14);
  // a curl as large as the divergence halves A: xi = 1/2
  EXPECT_NEAR(law.local(-1.0, -0.9, 1.0, 0.01, 1.0, 0.1), 0.05 / 1.05, 1e-14);
  // a strong steepening drives alpha to alpha_max, never beyond
  EXPECT_NEAR(law.next(0.0, -1.0, 0.0, 0.0, 1e-6, 1.0, 0.1), 1e4 / (1e4 + 1.0), 1e-12);  // H^2 A = 1e4
  EXPECT_LE(law.next(0.0, -1.0, 0.0, 0.0, 1e-9, 1.0, 0.1), 1.0);
  // no trigger in an expansion, or in a compression that relaxes
  EXPECT_EQ(law.local(1.0, 2.0, 0.0, 0.01, 1.0, 0.1), 0.0);
  EXPECT_EQ(law.local(-1.0, -2.0, 0.0, 0.01, 1.0, 0.1), 0.0);
}

TEST(ViscositySwitch, CullenDehnenAlphaDecaysExponentiallyToItsFloor) {
  const CullenDehnenLaw law{0.0, 1.0, 0.1};
  // tau = H / (decay c) = 0.1 / (0.1 * 1) = 1: alpha = e^(-dt) after dt without a trigger
  EXPECT_NEAR(law.next(1.0, 0.5, 0.5, 0.0, 0.5, 1.0, 0.1), std::exp(-0.5), 1e-15);
  // integrated exactly: two half intervals give one whole interval
  const double half = law.next(law.next(1.0, 0.5, 0.5, 0.0, 0.25, 1.0, 0.1), 0.5, 0.5, 0.0, 0.25, 1.0, 0.1);
  EXPECT_NEAR(half, law.next(1.0, 0.5, 0.5, 0.0, 0.5, 1.0, 0.1), 1e-15);
  // the floor alpha_min holds
  const CullenDehnenLaw floor{0.1, 1.0, 0.1};
  EXPECT_EQ(floor.next(0.1, 0.5, 0.5, 0.0, 10.0, 1.0, 0.1), 0.1);
  EXPECT_NEAR(floor.next(1.0, 0.5, 0.5, 0.0, 100.0, 1.0, 0.1), 0.1, 1e-15);
  // no interval (the first evaluation after a change): alpha kept
  EXPECT_EQ(law.next(0.7, -1.0, 0.0, 0.0, 0.0, 1.0, 0.1), 0.7);
}

/// A 32 x 32 periodic lattice of gas (rho = 1, u = 1) with velocity v(x, y), the whole pipeline of
/// summation density, ideal gas, standard forces and Monaghan viscosity with the switch `sw`.
test::StageBench gas_with_velocity(ViscSwitch sw, double (*vx)(double, double), double (*vy)(double, double)) {
  Params prm;
  prm.physics.visc_switch = sw;
  constexpr std::size_t n = 32;
  const double dx = 1.0 / n;
  test::StageBench b(prm, 2, n * n, test::pipeline_fields(prm, 2));
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {1, 1, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  test::jittered_lattice(b.p, n, dx, 0.0, 1.2 * dx, 1.0);
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    b.p[Field::Energy][i] = 1.0;
    b.p.v[0][i] = vx(b.p.x[0][i], b.p.x[1][i]);
    b.p.v[1][i] = vy(b.p.x[0][i], b.p.x[1][i]);
  }
  b.prepare(FieldSet{});
  b.run_pipeline();
  return b;
}

constexpr double kK = 2.0 * std::numbers::pi;  // one wave across the box [1/length]
double compress_x(double x, double) { return 0.1 * std::sin(kK * x); }
double shear_x(double, double y) { return 0.1 * std::sin(kK * y); }
double zero(double, double) { return 0.0; }

TEST(ViscositySwitch, StageMeasuresDivergenceAndCurlAndLimitsAlphaInShear) {
  const double scale = 0.1 * kK;  // |grad v| [1/time]
  double worst_div = 0.0, worst_curl = 0.0, alpha_shear = 0.0, alpha_peak = 0.0;
  {  // v_x = U sin(k x): div v = U k cos(k x), curl 0; alpha = visc.alpha near the extremes of div v
    test::StageBench b = gas_with_velocity(ViscSwitch::Balsara, compress_x, zero);
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      const double exact = scale * std::cos(kK * b.p.x[0][i]);
      worst_div = std::max(worst_div, std::abs(b.p[Field::DivV][i] - exact) / scale);
      if (std::abs(exact) > 0.9 * scale) alpha_peak = std::max(alpha_peak, std::abs(b.p[Field::ViscAlpha][i] - 1.0));
    }
  }
  {  // v_x = U sin(k y): div v = 0, |curl v| = U k |cos(k y)|; Balsara turns the viscosity off
    test::StageBench b = gas_with_velocity(ViscSwitch::Balsara, shear_x, zero);
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      const double exact = scale * std::abs(std::cos(kK * b.p.x[1][i]));
      worst_curl = std::max(worst_curl, std::abs(b.p[Field::CurlV][i] - exact) / scale);
      alpha_shear = std::max(alpha_shear, b.p[Field::ViscAlpha][i]);
    }
  }
  std::printf("32^2 lattice, M4: max |div v - exact| %.2e, max ||curl v| - exact| %.2e (of U k); alpha in shear "
              "<= %.2e, |alpha - 1| where |div v| > 0.9 U k <= %.2e\n",
              worst_div, worst_curl, alpha_shear, alpha_peak);
  EXPECT_LT(worst_div, 0.02);
  EXPECT_LT(worst_curl, 0.02);
  EXPECT_LT(alpha_shear, 1e-12);  // div v vanishes by symmetry on the lattice
  EXPECT_LT(alpha_peak, 0.02);
}

TEST(ViscositySwitch, CullenDehnenStartsAtAlphaMin) {
  test::StageBench b = gas_with_velocity(ViscSwitch::CullenDehnen, compress_x, zero);
  for (std::size_t i = 0; i < b.p.total(); ++i) ASSERT_EQ(b.p[Field::ViscAlpha][i], b.prm.visc.alpha_min) << i;
}

TEST(ViscositySwitch, RefusedWhereThereIsNoMonaghanViscosityToSwitch) {
  Physics ph;
  ph.visc_switch = ViscSwitch::CullenDehnen;
  EXPECT_EQ(ph.validate(), "");
  ph.viscosity = ViscType::Laplacian;
  EXPECT_NE(ph.validate().find("visc.switch = cullen_dehnen"), std::string::npos) << ph.validate();
  EXPECT_NE(ph.validate().find("physics.viscosity = laplacian"), std::string::npos) << ph.validate();
  ph.viscosity = ViscType::Monaghan;
  ph.force = ForceType::Corrected;
  EXPECT_NE(ph.validate().find("physics.force = corrected"), std::string::npos) << ph.validate();
  // its parameters are refused where the switch does not run
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("visc.alpha_max", "2", "test");
  try {
    cfg.validate();
    ADD_FAILURE() << "visc.alpha_max accepted without the switch";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("visc.alpha_max"), std::string::npos) << e.what();
  }
  cfg.set("visc.switch", "cullen_dehnen", "test");
  EXPECT_NO_THROW(cfg.validate());
}

}  // namespace
}  // namespace sph
