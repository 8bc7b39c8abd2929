// Every stage copies what it shares to the ghosts: after a whole pipeline on a box with periodic and
// mirror boundaries, each ghost carries its source's value of every shared field (sign-flipped where the
// field is a vector or tensor component mirrored an odd number of times), for every force formulation.
#include <gtest/gtest.h>

#include <bit>

#include "stage_test_util.h"

namespace sph {
namespace {

void check_ghosts(ForceType force, Boundary bx) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = force;
  prm.physics.viscosity = force == ForceType::Corrected ? ViscType::Laplacian : ViscType::Monaghan;
  prm.physics.xsph = Toggle::On;
  prm.physics.energy = Toggle::Off;
  const std::size_t n = 16;
  const double dx = 1.0 / n;
  test::StageBench b(prm, 2, n * n, test::pipeline_fields(prm, 2));
  b.domain.lo = {0, 0, 0};
  b.domain.hi = {1, 1, 1};
  b.domain.bc = {bx, Boundary::Wall, Boundary::Open};
  test::jittered_lattice(b.p, n, dx, 0.3, 1.3 * dx, prm.liquid.rho0);
  for (std::size_t i = 0; i < b.p.size(); ++i) {  // a non-uniform state, so that copies are visible
    b.p.v[0][i] = std::sin(6.0 * b.p.x[1][i]);
    b.p.v[1][i] = 0.3 * std::cos(5.0 * b.p.x[0][i]);
    b.p[Field::Density][i] = prm.liquid.rho0 * (1.0 + 0.01 * std::sin(7.0 * b.p.x[0][i] + 3.0 * b.p.x[1][i]));
  }
  b.prepare(FieldSet{}.add(Field::Density));
  ASSERT_GT(b.p.total(), b.p.size());
  b.run_pipeline();
  Pipeline pl(prm, 2);
  std::size_t checked = 0;
  for (const auto& stage : pl.stages()) {
    stage->shares().for_each([&](Field f) {
      const auto& a = b.p[f];
      const std::uint8_t axes = info(f).flip_axes;
      for (std::size_t g = 0; g < b.p.ghost_src.size(); ++g) {
        const std::size_t ghost = b.p.size() + g, src = b.p.ghost_src[g];
        const bool odd = std::popcount(static_cast<unsigned>(axes & b.p.ghost_flip[g])) & 1u;
        ASSERT_EQ(a[ghost], odd ? -a[src] : a[src]) << stage->name() << " field " << info(f).key << " ghost " << g;
        ++checked;
      }
    });
  }
  EXPECT_GT(checked, 1000u);
}

TEST(StageGhosts, PeriodicAndMirrorCopiesOfEverySharedField) {
  for (ForceType f : {ForceType::Standard, ForceType::StandardCorrected, ForceType::Corrected}) {
    check_ghosts(f, Boundary::Periodic);
    check_ghosts(f, Boundary::Wall);
  }
}

}  // namespace
}  // namespace sph
