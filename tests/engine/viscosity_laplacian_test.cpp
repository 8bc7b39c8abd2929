// The Laplacian viscosity from first derivatives (seed 004; Morris et al. 1997) and the corrected
// formulation's viscous stress (seed 001 eqs. 51-52): on a periodic lattice with the shear flow
// v_x = U sin(k y), both give dv/dt = nu d2v_x/dy2 = -nu k^2 U sin(k y) (no pressure gradient).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "stage_test_util.h"

namespace sph {
namespace {

struct Shear {
  double max_rel_err = 0.0;  ///< max |a_x - exact| / (nu k^2 U) over the particles
  double max_ay = 0.0;       ///< the transverse acceleration should vanish
};

Shear shear(ForceType force) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = force;
  prm.physics.viscosity = ViscType::Laplacian;
  prm.physics.energy = Toggle::Off;
  prm.kernel.type = KernelType::WendlandC2;
  prm.visc.nu = 0.01;
  const std::size_t n = 40;
  const double L = 1.0, dx = L / n, U = 1.0, k = 2.0 * std::numbers::pi / L;
  test::StageBench b(prm, 2, n * n, test::pipeline_fields(prm, 2));
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {L, L, 1};
  b.domain.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  test::jittered_lattice(b.p, n, dx, 0.0, 1.6 * dx, prm.liquid.rho0);
  for (std::size_t i = 0; i < b.p.size(); ++i) b.p.v[0][i] = U * std::sin(k * b.p.x[1][i]);
  b.prepare(FieldSet{}.add(Field::Density));
  b.run_pipeline();
  Shear s;
  const double scale = prm.visc.nu * k * k * U;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const double exact = -scale * std::sin(k * b.p.x[1][i]);
    s.max_rel_err = std::max(s.max_rel_err, std::abs(b.p.a[0][i] - exact) / scale);
    s.max_ay = std::max(s.max_ay, std::abs(b.p.a[1][i]) / scale);
  }
  std::printf("%s: max |a_x - exact| / (nu k^2 U) = %.3e\n", force == ForceType::Standard ? "standard" : "corrected",
              s.max_rel_err);
  return s;
}

TEST(ViscosityLaplacian, StandardFormDiffusesAShearWave) {
  const Shear s = shear(ForceType::Standard);
  EXPECT_LT(s.max_rel_err, 0.03) << "Morris form, 40 particles per wavelength";
  EXPECT_LT(s.max_ay, 1e-8);
}

TEST(ViscosityLaplacian, CorrectedStressDiffusesAShearWave) {
  const Shear s = shear(ForceType::Corrected);
  EXPECT_LT(s.max_rel_err, 0.03) << "stress from the corrected velocity gradient";
  EXPECT_LT(s.max_ay, 1e-8);
}

}  // namespace
}  // namespace sph
