// The incompressible elliptical drop (Monaghan 1994, JCP 110, 399; seed 001 §7.1): a circle of radius 1
// with v = (-A x, A y) stays an ellipse with semi-axes a (along x) and 1/a (along y) while
//   dA/dt = A^2 (a^4 - 1)/(a^4 + 1),   da/dt = -a A,   A(0) = A0, a(0) = 1.
#pragma once

namespace sph::scenes {

struct DropState {
  double A;  ///< velocity gradient [1/time]
  double a;  ///< minor semi-axis (along x) [length]; the major one is 1/a
};

/// The solution at time t >= 0, by classical RK4 with steps of at most 1e-7 / (A0/100) (converged to
/// ~1e-12 against halving the step).
DropState drop_ode(double A0, double t);

}  // namespace sph::scenes
