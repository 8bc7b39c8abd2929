// Noh's exact solution: the jump conditions (rho2 = 16, P2 = 16/3, shock at t/3 for gamma = 5/3 in 2D)
// against the Rankine-Hugoniot relations in the shock's frame.
#include "reference/noh_solution.h"

#include <gtest/gtest.h>

namespace sph::scenes {
namespace {

TEST(NohSolution, JumpConditionsHoldAtTheShock) {
  const Noh noh;  // 2D, gamma 5/3, rho0 = v0 = 1
  EXPECT_DOUBLE_EQ(noh.post_shock_density(), 16.0);
  EXPECT_DOUBLE_EQ(noh.shock_radius(0.6), 0.2);
  const double t = 0.6, R = noh.shock_radius(t), U = noh.shock_speed();
  const NohState in = noh.state(R * (1 - 1e-12), t), out = noh.state(R * (1 + 1e-12), t);
  EXPECT_NEAR(in.P, 16.0 / 3.0, 1e-12);
  EXPECT_NEAR(out.rho, 4.0, 1e-9);  // 1 + t/r at r = t/3
  // mass and momentum fluxes through the shock in its frame (Landau & Lifshitz §85)
  const double w_out = out.v - U, w_in = in.v - U;
  EXPECT_NEAR(out.rho * w_out, in.rho * w_in, 1e-9);
  EXPECT_NEAR(out.P + out.rho * w_out * w_out, in.P + in.rho * w_in * w_in, 1e-9);
  // energy flux: rho w (u + P/rho + w^2/2)
  EXPECT_NEAR(out.rho * w_out * (out.u + 0.5 * w_out * w_out), in.rho * w_in * (in.u + in.P / in.rho + 0.5 * w_in * w_in),
              1e-9);
  // 3D: rho2 = 64 (Noh 1987)
  EXPECT_DOUBLE_EQ((Noh{3, 5.0 / 3.0, 1.0, 1.0}.post_shock_density()), 64.0);
}

}  // namespace
}  // namespace sph::scenes
