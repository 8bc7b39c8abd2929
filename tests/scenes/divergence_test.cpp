// Runs that blow up are stopped and reported, not written out or crawled through: a liquid stepped at
// several times its Courant limit explodes within tens of steps and World::step throws DivergedError
// (a non-finite value, one beyond single precision, a collapsed timestep or a total energy grown far past
// its initial scale).
#include <gtest/gtest.h>

#include <string>

#include "sph/world.h"

namespace sph {
namespace {

TEST(Divergence, AnUnstableLiquidIsStoppedWithAReason) {
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank");
  cfg.set("scene.dx", "0.05", "test");
  cfg.set("time.dt", "0.01", "test");  // c0 = 44 m/s, h = 0.065 m: dt = 0.01 s is ~7 times the limit
  World w(cfg);
  std::string why;
  try {
    for (int s = 0; s < 400; ++s) w.step();
  } catch (const DivergedError& e) {
    why = e.what();
  }
  ASSERT_FALSE(why.empty()) << "400 steps at 7x the Courant limit did not diverge";
  EXPECT_NE(why.find("diverged"), std::string::npos) << why;
  std::printf("%s\n", why.c_str());
}

TEST(Divergence, AFiniteBlowUpIsCaughtByTheEnergyGuard) {
  // The same at 3x the limit: the velocities run away while staying finite for a while; the energy
  // guard (E_tot > E_tot(0) + 10 (|E_kin| + |E_int| + |E_pot|)) or the single-precision bound on the
  // state (a collapsing particle's Tait pressure passes 3.4e38 Pa first: 3.75e40 at step 13) stops it
  // before any NaN.
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank");
  cfg.set("scene.dx", "0.05", "test");
  cfg.set("time.dt", "0.004", "test");
  World w(cfg);
  std::string why;
  try {
    for (int s = 0; s < 2000; ++s) w.step();
  } catch (const DivergedError& e) {
    why = e.what();
  }
  ASSERT_FALSE(why.empty()) << "2000 steps at 3x the Courant limit did not diverge";
  std::printf("%s\n", why.c_str());
  EXPECT_TRUE(why.find("total energy grew") != std::string::npos ||
              why.find("beyond single precision") != std::string::npos)
      << why;
}

}  // namespace
}  // namespace sph
