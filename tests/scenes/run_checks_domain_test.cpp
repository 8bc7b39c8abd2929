// The domain guard (engine/src/world/run_checks_domain.cpp): in a scene with wall particles, fluid outside
// the domain box along an open axis is warned about, naming the count and the first particle; fluid
// inside is not, and a scene without walls (the box only frames the view) is never warned about.
#include <gtest/gtest.h>

#include "sph/run_checks.h"

namespace sph {
namespace {

/// Three particles in 2D: fluid at (0.5, 0.5) and (x, y), and a wall at (0.5, -0.05) unless `no_wall`.
Particles three(double x, double y, bool no_wall = false) {
  Particles p(2, 3, FieldSet{});
  const double xs[3] = {0.5, x, 0.5}, ys[3] = {0.5, y, -0.05};
  for (std::size_t i = 0; i < 3; ++i) {
    p.x[0][i] = xs[i];
    p.x[1][i] = ys[i];
    p.id[i] = static_cast<std::int64_t>(i);
  }
  if (!no_wall) p.kind[2] = static_cast<std::uint8_t>(Kind::Wall);
  p.partition_by_kind();
  return p;
}

Domain box() {
  Domain d;
  d.lo = {-0.1, -0.1, 0.0};
  d.hi = {1.1, 2.0, 1.0};
  return d;
}

TEST(RunChecksDomain, FluidBelowTheWallsIsWarnedAbout) {
  RunChecks c;
  c.check_domain(three(0.3, -0.4), box(), 7, 0.25);
  ASSERT_EQ(c.warnings().size(), 1u);
  EXPECT_EQ(c.warnings()[0].kind, "domain");
  EXPECT_EQ(c.warnings()[0].particle, 1);
  EXPECT_EQ(c.warnings()[0].step, 7);
  EXPECT_NE(c.warnings()[0].message.find("1 fluid particles are outside the domain box (particle 1 at (0.3, -0.4"),
            std::string::npos)
      << c.warnings()[0].message;
}

TEST(RunChecksDomain, FluidInsideOrAPeriodicAxisOrNoWallsIsNot) {
  RunChecks c;
  c.check_domain(three(0.3, 1.9), box(), 1, 0.1);  // inside
  Domain periodic = box();
  periodic.bc[1] = Boundary::Periodic;              // the wrap is another guard's
  c.check_domain(three(0.3, -0.4), periodic, 2, 0.2);
  c.check_domain(three(0.3, -0.4, true), box(), 3, 0.3);  // no walls: the box frames the view only
  EXPECT_TRUE(c.warnings().empty());
}

}  // namespace
}  // namespace sph
