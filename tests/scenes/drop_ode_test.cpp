// The incompressible elliptical-drop ODE (Monaghan 1994; reference/drop_ode.h) against values computed
// independently (RK4 to convergence; ../shared/REFERENCES.md) and against its own invariants.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/drop_ode.h"

namespace sph::scenes {
namespace {

TEST(DropOde, MatchesTheTabulatedSemiAxes) {
  struct Row { double t, a, b; };
  // minor a and major 1/a at A0 = 100 /s, 5 decimals (the table's precision)
  for (const Row& r : {Row{0.0008, 0.92327, 1.08310}, Row{0.0020, 0.82083, 1.21828}, Row{0.0038, 0.69482, 1.43922},
                       Row{0.0050, 0.62705, 1.59476}, Row{0.0076, 0.51427, 1.94452}, Row{0.0100, 0.43946, 2.27552}}) {
    const DropState s = drop_ode(100.0, r.t);
    EXPECT_NEAR(s.a, r.a, 6e-6) << "t = " << r.t;
    EXPECT_NEAR(1.0 / s.a, r.b, 6e-6) << "t = " << r.t;
  }
}

TEST(DropOde, StartsAtTheCircleAndScalesWithA0) {
  const DropState s0 = drop_ode(100.0, 0.0);
  EXPECT_EQ(s0.a, 1.0);
  EXPECT_EQ(s0.A, 100.0);
  // the ODE is invariant under A -> k A, t -> t / k: a(t; k A0) = a(k t; A0)
  EXPECT_NEAR(drop_ode(200.0, 0.0038).a, drop_ode(100.0, 0.0076).a, 1e-10);
}

}  // namespace
}  // namespace sph::scenes
