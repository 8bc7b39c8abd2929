// The start check of a fixed timestep against pericentre passages (engine/src/world/
// run_checks_timestep.cpp) and the energy bounds of the N-body scenes: kepler at e = 0.9 and its default
// dt is warned about before the first step, naming time.dt, the pair and its pericentre, and its energy
// leaves the bound (the run stops or ends beyond it); the seed's orbit runs clean; an adaptive run of
// e = 0.9 (time.dt = 0, cfl 0.002) stays within the bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "sph/world.h"

namespace sph {
namespace {

const RunWarning* find(const World& w, const std::string& kind) {
  for (const RunWarning& x : w.checks().warnings())
    if (x.kind == kind) return &x;
  return nullptr;
}

RunConfig kepler(double e) {
  RunConfig cfg = RunConfig::from_scene("kepler");
  cfg.set("scene.e", std::to_string(e), "test");
  return cfg;
}

TEST(KeplerTimestep, EccentricOrbitAtTheDefaultDtIsWarnedAboutThenLeavesTheBound) {
  World w(kepler(0.9));
  const RunWarning* t = find(w, "timestep");
  ASSERT_NE(t, nullptr);
  std::printf("%s\n", t->message.c_str());
  EXPECT_NE(t->message.find("time.dt = 0.002 is too large for the pericentre of bodies 0-1 (q = 0.0526 AU"),
            std::string::npos);
  EXPECT_NE(t->message.find("use time.dt <= "), std::string::npos);
  bool stopped = false;
  try {
    w.advance_to(1.0);  // 2.6 orbits: a pericentre passage at t = 0.19
  } catch (const DivergedError&) {
    stopped = true;
  }
  EXPECT_TRUE(stopped || w.checks().energy_beyond_bound(w.config()));
}

TEST(KeplerTimestep, TheSeedsOrbitRunsCleanAtItsDefaults) {
  World w(RunConfig::from_scene("kepler"));
  w.advance_to(w.params().time.t_end);
  for (const RunWarning& x : w.checks().warnings()) ADD_FAILURE() << x.kind << ": " << x.message;
  EXPECT_FALSE(w.checks().energy_beyond_bound(w.config()));
}

TEST(KeplerTimestep, AdaptiveStepsKeepAnEccentricOrbitWithinTheBound) {
  // dt = cfl sqrt(r^3 / mu): the pericentre passage gets its steps. The peak |dE| of the passage is
  // about 5 cfl^2 of the energy scale (cfl 0.003: 4.5e-5, beyond the bound 3e-5: warned, exit 8)
  RunConfig cfg = kepler(0.9);
  cfg.set("time.dt", "0", "test");
  cfg.set("time.cfl", "0.002", "test");
  World w(cfg);
  EXPECT_EQ(find(w, "timestep"), nullptr);  // no fixed dt to warn about
  w.advance_to(0.4);                        // one orbit (0.38 yr), its pericentre passage at 0.19
  std::printf("kepler e = 0.9, adaptive cfl 0.002: %lld steps to t = 0.4, dE = %.3g\n",
              static_cast<long long>(w.steps()), w.report().reference_value("dE"));
  for (const RunWarning& x : w.checks().warnings()) ADD_FAILURE() << x.kind << ": " << x.message;
  EXPECT_FALSE(w.checks().energy_beyond_bound(w.config()));
}

TEST(KeplerTimestep, SolarSystemAndTheFallRunCleanAtTheirDefaults) {
  for (const char* scene : {"solar_system", "two_body_fall"}) {
    World w(RunConfig::from_scene(scene));
    w.advance_to(std::min(1.0, w.params().time.t_end));
    for (const RunWarning& x : w.checks().warnings()) ADD_FAILURE() << scene << ": " << x.kind << ": " << x.message;
  }
}

}  // namespace
}  // namespace sph
