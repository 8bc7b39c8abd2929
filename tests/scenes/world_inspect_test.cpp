// Report::inspect, the particle inspector: the terms of a particle's momentum and energy equations add up
// to the rates the stages compute for it (gas: standard grad-h with Monaghan viscosity, conduction and
// the energy equation; liquids: standard-corrected with dummy walls and gravity, corrected stress form,
// standard with XSPH), its neighbours carry its summation density, the shock heats by viscosity, and
// inspecting a run leaves it bitwise unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"
#include "sph/world.h"

namespace sph {
namespace {

/// |sum of the terms - the re-evaluated rate| against the terms' own size (the round-off scale).
struct Balance {
  double a_err = 0.0, a_scale = 0.0, du_err = 0.0, du_scale = 0.0;
};

Balance balance(const Inspection& in) {
  Vec3 a;
  double du = 0.0;
  Balance b;
  for (const InspectTerm& t : in.terms) {
    a += t.a;
    du += t.dudt;
    b.a_scale += t.a_scale;
    b.du_scale += t.dudt_scale;
  }
  b.a_err = (a - in.a_total).norm();
  b.du_err = std::abs(du - in.dudt_total);
  return b;
}

/// Every fluid particle of w whose id is a multiple of `stride`: the terms add up to 1e-10 of their size.
void expect_terms_add_up(const World& w, std::int64_t stride, const char* what) {
  std::size_t checked = 0;
  for (std::int64_t id = 0; id < static_cast<std::int64_t>(w.particles().size()); id += stride) {
    const auto in = w.report().inspect(id);
    ASSERT_TRUE(in.has_value());
    if (in->wall) continue;
    const Balance b = balance(*in);
    ASSERT_GT(b.a_scale, 0.0) << what << " id " << id;
    EXPECT_LE(b.a_err, 1e-10 * b.a_scale) << what << " id " << id;
    EXPECT_LE(b.du_err, 1e-10 * b.du_scale + 1e-300) << what << " id " << id;
    ++checked;
  }
  EXPECT_GT(checked, 5u) << what;
}

const InspectTerm* term(const Inspection& in, const std::string& name) {
  for (const InspectTerm& t : in.terms)
    if (t.name == name) return &t;
  return nullptr;
}

TEST(WorldInspect, SodTermsAddUpAndTheShockHeatsByViscosity) {
  World w(RunConfig::from_scene("sod"));
  w.advance_to(0.1);
  expect_terms_add_up(w, 7, "sod");
  // the particle heating fastest sits in the shock: its viscous heating is positive
  const Particles& p = w.particles();
  std::size_t hot = 0;
  for (std::size_t i = 0; i < p.fluid(); ++i)
    if (p[Field::EnergyRate][i] > p[Field::EnergyRate][hot]) hot = i;
  const auto in = w.report().inspect(p.id[hot]);
  ASSERT_TRUE(in.has_value());
  EXPECT_EQ(in->formulation, "standard");
  ASSERT_NE(term(*in, "pressure"), nullptr);
  ASSERT_NE(term(*in, "conduction"), nullptr);
  const InspectTerm* visc = term(*in, "artificial viscosity Pi");
  ASSERT_NE(visc, nullptr);
  EXPECT_GT(visc->dudt, 0.0);
  EXPECT_GT(in->dudt_total, 0.0);
  // exact solution: the shock of Sod is at x = 0.850 t (Toro's Table 4.1 test 1 state, speed 1.7522)
  EXPECT_NEAR(in->x.x, 1.7522 * 0.1, 0.03);
}

TEST(WorldInspect, NeighboursCarryTheSummationDensity) {
  World w(RunConfig::from_scene("sod"));
  w.advance_to(0.05);
  for (std::int64_t id : {10, 300, 420}) {
    const auto in = w.report().inspect(id);
    ASSERT_TRUE(in.has_value());
    // rho_a = m_a W(0, h_a) + sum_b m_b W(r_ab, h_a): the shares and the self term make 1
    double sum = in->m * Kernel(KernelType::M4, 1).W(0.0, in->h) / in->rho;
    for (const InspectNeighbour& n : in->neighbour_list) sum += n.share;
    EXPECT_NEAR(sum, 1.0, 1e-5) << "id " << id;
    EXPECT_GT(in->neighbour_list.size(), 3u);
    EXPECT_GE(in->h_iterations, 0.0);
    EXPECT_GT(in->omega, 0.5);
    // the support drawn around it (M4: 2 h) holds every neighbour listed
    EXPECT_DOUBLE_EQ(in->support, 2.0 * in->h);
    for (const InspectNeighbour& n : in->neighbour_list) EXPECT_LE(n.r, in->support) << "id " << id;
  }
}

TEST(WorldInspect, StoredAndReEvaluatedRatesAgree) {
  // At the start the run's rates belong to its state: the re-evaluation differs only by the h solve's
  // tolerance (1e-6). After leapfrog steps it evaluated at the predicted velocity: O(dt) apart.
  World w(RunConfig::from_scene("sod"));
  for (std::int64_t id : {100, 399, 401}) {
    const auto in = w.report().inspect(id);
    const Balance b = balance(*in);
    EXPECT_LE((in->a_total - in->a_stored).norm(), 1e-4 * b.a_scale + 1e-12) << id;
  }
  w.advance_to(0.05);
  for (std::int64_t id : {100, 399, 401}) {
    const auto in = w.report().inspect(id);
    const Balance b = balance(*in);
    EXPECT_LE((in->a_total - in->a_stored).norm(), 0.05 * b.a_scale + 1e-12) << id;
  }
}

/// The elliptical drop at dx = 0.05 with these settings.
RunConfig drop(std::initializer_list<std::pair<const char*, const char*>> sets) {
  RunConfig cfg = RunConfig::from_scene("elliptical_drop");
  cfg.set("scene.dx", "0.05", "test");
  for (const auto& [k, v] : sets) cfg.set(k, v, "test");
  return cfg;
}

TEST(WorldInspect, LiquidsTermsAddUp) {
  {  // standard-corrected with dummy walls and gravity (the default dam break)
    RunConfig cfg = RunConfig::from_scene("dam_break");
    cfg.set("scene.dx", "0.05", "test");
    World w(cfg);
    for (int k = 0; k < 20; ++k) w.step();
    expect_terms_add_up(w, 61, "dam_break");
    const auto in = w.report().inspect(0);
    ASSERT_TRUE(in.has_value());
    EXPECT_EQ(in->formulation, "standard-corrected");
    const InspectTerm* g = term(*in, "body force: uniform g");
    ASSERT_NE(g, nullptr);
    EXPECT_NEAR(g->a.y, -9.81, 1e-12 * (1.0 + in->a_total.norm()));  // (a + g) - a, rounded
    EXPECT_NEAR(g->a.x, 0.0, 1e-12 * (1.0 + in->a_total.norm()));
  }
  {  // corrected stress form with the viscous stress
    World w(drop({{"physics.force", "corrected"}, {"physics.viscosity", "laplacian"}, {"visc.nu", "0.01"}}));
    for (int k = 0; k < 10; ++k) w.step();
    expect_terms_add_up(w, 97, "elliptical_drop_corrected");
    const auto in = w.report().inspect(5);
    EXPECT_EQ(in->formulation, "corrected (stress form)");
    EXPECT_NE(term(*in, "viscous stress"), nullptr);
  }
  {  // standard with XSPH and Monaghan viscosity
    World w(drop({{"physics.force", "standard"}, {"physics.xsph", "on"}}));
    for (int k = 0; k < 10; ++k) w.step();
    expect_terms_add_up(w, 97, "elliptical_drop_standard");
  }
}

TEST(WorldInspect, InspectingLeavesTheRunUnchanged) {
  World a(RunConfig::from_scene("sod")), b(RunConfig::from_scene("sod"));
  for (int k = 0; k < 40; ++k) {  // across two Morton reorderings (every 16 steps)
    a.step();
    b.step();
    ASSERT_TRUE(b.report().inspect(k * 7 % 450).has_value());
  }
  EXPECT_EQ(test::state_hash(a.particles()), test::state_hash(b.particles()));
  EXPECT_EQ(a.time(), b.time());
}

TEST(WorldInspect, UnknownIdAndWalls) {
  World w(RunConfig::from_scene("sod"));
  EXPECT_FALSE(w.report().inspect(-1).has_value());
  EXPECT_FALSE(w.report().inspect(static_cast<std::int64_t>(w.particles().size())).has_value());
  RunConfig cfg = RunConfig::from_scene("dam_break");
  cfg.set("scene.dx", "0.05", "test");
  World d(cfg);
  const Particles& p = d.particles();
  const auto in = d.report().inspect(p.id[p.fluid()]);  // the first wall particle
  ASSERT_TRUE(in.has_value());
  EXPECT_TRUE(in->wall);
  EXPECT_TRUE(in->terms.empty());
}

}  // namespace
}  // namespace sph
