// The inspector's re-evaluation (engine/src/inspect/fresh_evaluation.cpp): on a copy of the state it
// computes the same rates as the stages run in place, attributes to each stage what it added (a uniform
// body force adds exactly g), and leaves the state it was given unchanged.
#include <gtest/gtest.h>

#include "inspect/fresh_evaluation.h"
#include "stage_test_util.h"

namespace sph {
namespace {

TEST(FreshEvaluation, SameRatesAsThePipelineAndOneDeltaPerStage) {
  Params prm;
  prm.physics.density = DensityMode::Continuity;
  prm.physics.smoothing = HMode::Fixed;
  prm.physics.eos = EosType::Tait;
  prm.physics.force = ForceType::Standard;
  prm.physics.viscosity = ViscType::Monaghan;
  prm.physics.body_force = BodyForce::Uniform;
  prm.body.gy = -9.81;
  constexpr std::size_t n = 10;
  test::StageBench b(prm, 2, n * n, test::pipeline_fields(prm, 2));
  b.domain.hi = {1.0, 1.0, 1.0};
  b.domain.bc = {Boundary::Periodic, Boundary::Periodic, Boundary::Open};
  test::jittered_lattice(b.p, n, 0.1, 0.3, 0.13, 1000.0);
  for (std::size_t i = 0; i < n * n; ++i) b.p.v[0][i] = 0.5 * std::sin(6.0 * b.p.x[1][i]);
  const Particles before = b.p;
  const FreshInputs in{b.prm, b.kernel, b.domain, 1.3, 0.1, 0.0};
  const std::size_t i = 37;
  FreshEvaluation e = evaluate_fresh(in, b.p, i);
  // the source state is untouched
  EXPECT_EQ(b.p.x[0], before.x[0]);
  EXPECT_EQ(b.p.a[0], before.a[0]);
  // the same rates as the pipeline run in place
  b.prepare(FieldSet{}.add(Field::Density));
  b.run_pipeline();
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(e.p.a[k][i], b.p.a[k][i], 1e-12 * (1.0 + std::abs(b.p.a[k][i])));
  // one delta per stage; the force stage's is its whole result, the body force's is g
  ASSERT_EQ(e.deltas.size(), e.pipeline->stages().size());
  bool force = false, body = false;
  for (const StageDelta& d : e.deltas) {
    if (d.sets) force = true;
    if (d.stage == "body force: uniform g") {
      body = true;
      EXPECT_NEAR(d.a.x, 0.0, 1e-12 * (1.0 + std::abs(b.p.a[0][i])));
      EXPECT_NEAR(d.a.y, -9.81, 1e-12 * (1.0 + std::abs(b.p.a[1][i])));  // (a + g) - a, rounded
    }
  }
  EXPECT_TRUE(force);
  EXPECT_TRUE(body);
}

}  // namespace
}  // namespace sph
