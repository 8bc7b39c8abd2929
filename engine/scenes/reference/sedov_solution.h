// The Sedov-Taylor point blast: the self-similar flow after an energy E is released at a point of a
// uniform gas of density rho1 at rest and zero pressure (Sedov 1959, "Similarity and Dimensional Methods
// in Mechanics", ch. IV §11), for dimension d = 1, 2, 3 (planar, cylindrical, spherical) and
// 1 < gamma < 2. The shock is at R(t) = xi0 (E t^2 / rho1)^(1/(d+2)); behind it rho, v, P are the
// post-shock (Rankine-Hugoniot, strong shock) values times functions of xi = r/R alone.
// The profiles are Sedov's closed-form parametric solution for a uniform ambient density, written in
// the variables of Kamm & Timmes 2007 ("On efficient generation of numerically robust Sedov
// solutions", LA-UR-07-2849, §2, the case omega = 0); xi0 follows from the energy integral, evaluated
// here by quadrature.
#pragma once

#include <vector>

namespace sph::scenes {

class SedovSolution {
 public:
  /// Profiles in units of the post-shock values: f = rho/rho2, g = v/v2, h = P/P2 at xi = r/R.
  struct Shape {
    double xi = 0, f = 0, g = 0, h = 0;
  };
  struct State {
    double rho = 0, v = 0, P = 0;  ///< density, radial velocity, pressure
  };

  SedovSolution(int dim, double gamma);

  int dim() const { return dim_; }
  double gamma() const { return gamma_; }
  /// The energy integral: E = alpha rho1 R^(d+2) / t^2 (alpha = xi0^-(d+2)).
  double alpha() const { return alpha_; }
  double xi0() const { return xi0_; }
  /// Shock radius [length] for blast energy E (per unit length in 2D, per unit area in 1D, both sides).
  double shock_radius(double E, double rho1, double t) const;
  /// The profiles at parameter y = x2 in (0, 1] (y = 1 at the shock, y -> 0 at the centre): exact.
  Shape at_parameter(double y) const;
  /// The profiles at xi in [0, 1], solved for the parameter (bisection in log y to round-off).
  Shape solve_xi(double xi) const;
  /// The profiles at xi in [0, 1] (interpolated from a table of 4001 points in xi; exact at the ends).
  Shape at_xi(double xi) const;
  /// The flow at distance r and time t > 0; the ambient gas (rho1, 0, 0) outside R(t).
  State state(double r, double t, double E, double rho1) const;

 private:
  int dim_;
  double gamma_;
  double a_, b_, c_, d_, e_;                 // Kamm & Timmes eqs. (31)-(34), omega = 0
  double al0_, al1_, al2_, al3_, al4_, al5_;  // their exponents alpha_0 ... alpha_5
  double alpha_ = 0, xi0_ = 0;
  std::vector<Shape> table_;  // at xi = k / (table_.size() - 1)
};

}  // namespace sph::scenes
