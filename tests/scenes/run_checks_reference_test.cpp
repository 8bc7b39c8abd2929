// The reference guard (engine/src/world/run_checks_reference.cpp): a value outside what a scene's
// reference assumes is warned about at the start, naming the key; an error norm beyond the scene's bound
// at an output is warned about, naming the column, but not while it is NaN (not measured yet), before the
// bound's start time or after the reference stops applying. Every scene's bounds name columns of its
// reference and every assumption a value that exists, and every scene at its defaults is inside them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sph/scene.h"
#include "sph/world.h"

namespace sph {
namespace {

const RunWarning* find(const RunChecks& c, const std::string& kind) {
  for (const RunWarning& x : c.warnings())
    if (x.kind == kind) return &x;
  return nullptr;
}

RunConfig scene(const std::string& name, const std::string& key = "", const std::string& value = "") {
  RunConfig cfg = RunConfig::from_scene(name);
  if (!key.empty()) cfg.set(key, value, "test");
  return cfg;
}

TEST(ReferenceGuard, EveryBoundNamesAColumnAndEveryAssumptionAValueAndTheDefaultsAreInside) {
  for (const SceneSpec& s : scene_registry()) {
    SCOPED_TRACE(s.name);
    const RunConfig cfg = RunConfig::from_scene(s.name);
    if (!s.error_bounds.empty()) {
      ASSERT_TRUE(s.reference);
      const std::vector<RefColumn> cols = s.reference(cfg.params, cfg.values)->columns();
      for (const ErrorBound& b : s.error_bounds) {
        EXPECT_GE(find_column(cols, b.column), 0) << b.column;
        EXPECT_GT(b.max, 0.0) << b.column;
      }
    }
    RunChecks c;
    c.check_assumptions(cfg);
    EXPECT_EQ(find(c, "assumption"), nullptr) << find(c, "assumption")->message;
    for (const RefAssumption& a : s.assumptions) {  // an unknown key reads as NaN: outside any range
      RefAssumption far = a;
      far.lo = -std::numeric_limits<double>::max();
      far.hi = std::numeric_limits<double>::max();
      SceneSpec one = s;
      one.assumptions = {far};
      RunConfig with = cfg;
      with.scene = &one;
      RunChecks d;
      d.check_assumptions(with);
      EXPECT_EQ(find(d, "assumption"), nullptr) << a.key << " does not name a number of the scene";
    }
  }
}

TEST(ReferenceGuard, AValueOutsideTheAssumptionsIsWarnedAboutNamingItsKey) {
  RunChecks c;
  c.check_assumptions(scene("sod", "scene.n_left", "100"));
  const RunWarning* w = find(c, "assumption");
  ASSERT_NE(w, nullptr);
  EXPECT_NE(w->message.find("scene.n_left = 100, where the reference assumes scene.n_left in [400, 1e+06]"),
            std::string::npos) << w->message;

  RunChecks d;  // a derived value: the Noh gas must be cold against the inflow
  d.check_assumptions(scene("noh", "scene.u0", "0.01"));
  ASSERT_NE(find(d, "assumption"), nullptr);
  EXPECT_NE(find(d, "assumption")->message.find("u0 / v0^2 = 0.01"), std::string::npos);

  RunChecks e;  // a run parameter: the Kepler orbit is that of point masses
  e.check_assumptions(scene("kepler", "gravity.eps", "0.01"));
  ASSERT_NE(find(e, "assumption"), nullptr);
  EXPECT_NE(find(e, "assumption")->message.find("gravity.eps = 0.01"), std::string::npos);
}

TEST(ReferenceGuard, AnErrorBeyondItsBoundIsWarnedAboutNamingTheColumnOnlyWhileItIsMeasuredAndApplies) {
  const RunConfig cfg = scene("sod");  // bound L1_rho <= 4.5e-3; the reference applies until t = 0.2968
  const auto ref = cfg.scene->reference(cfg.params, cfg.values);
  const std::vector<RefColumn> cols = ref->columns();
  const int k = find_column(cols, "L1_rho");
  ASSERT_GE(k, 0);
  std::vector<double> v(cols.size(), 0.0);
  RunChecks c;
  v[static_cast<std::size_t>(k)] = 4.4e-3;  // within
  c.check_error_bounds(cfg, ref.get(), cols, v, 10, 0.1);
  v[static_cast<std::size_t>(k)] = std::nan("");  // not measured
  c.check_error_bounds(cfg, ref.get(), cols, v, 11, 0.11);
  v[static_cast<std::size_t>(k)] = 0.02;  // beyond, after the reference stops applying
  c.check_error_bounds(cfg, ref.get(), cols, v, 50, 0.3);
  EXPECT_TRUE(c.warnings().empty());
  c.check_error_bounds(cfg, ref.get(), cols, v, 12, 0.12);  // beyond, while it applies
  const RunWarning* w = find(c, "accuracy:L1_rho");
  ASSERT_NE(w, nullptr);
  EXPECT_NE(w->message.find("L1_rho = 0.02 at t = 0.12, beyond this scene's bound 0.0045"), std::string::npos)
      << w->message;
  EXPECT_EQ(w->message.find("differs"), std::string::npos) << w->message;  // at the scene's defaults
  // a run away from the defaults, where the bound was measured, says how
  const RunConfig m6 = scene("sod", "kernel.type", "M6");
  RunChecks changed;
  changed.check_error_bounds(m6, ref.get(), cols, v, 12, 0.12);
  ASSERT_NE(find(changed, "accuracy:L1_rho"), nullptr);
  EXPECT_NE(find(changed, "accuracy:L1_rho")->message.find("; this run differs from them in kernel.type=M6)"),
            std::string::npos)
      << find(changed, "accuracy:L1_rho")->message;

  const RunConfig poly = scene("polytrope");  // profile_err is bounded from t = 1 (the relaxation before)
  const auto pref = poly.scene->reference(poly.params, poly.values);
  std::vector<double> pv(pref->columns().size(), 0.5);
  RunChecks d;
  d.check_error_bounds(poly, pref.get(), pref->columns(), pv, 5, 0.5);
  EXPECT_TRUE(d.warnings().empty());
  d.check_error_bounds(poly, pref.get(), pref->columns(), pv, 30, 1.0);
  EXPECT_NE(find(d, "accuracy:profile_err"), nullptr);
}

TEST(ReferenceGuard, ACoarseSodRunIsWarnedAboutAtTheStartAndAtItsOutputs) {
  World w(scene("sod", "scene.n_left", "100"));  // L1_rho 0.0075 at t = 0.05
  ASSERT_NE(find(w.checks(), "assumption"), nullptr);
  while (w.time() < 0.05 - 1e-12) w.step(0.05 - w.time());
  EXPECT_EQ(find(w.checks(), "accuracy:L1_rho"), nullptr);  // only outputs are checked
  w.check_output();
  EXPECT_NE(find(w.checks(), "accuracy:L1_rho"), nullptr);

  World d(scene("sod"));  // the defaults: 3.0e-3 at t = 0.2
  d.advance_to(0.2);
  d.check_output();
  EXPECT_TRUE(d.checks().warnings().empty());
}

}  // namespace
}  // namespace sph
