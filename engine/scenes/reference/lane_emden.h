// The Lane-Emden equation (seed 003 eqs. 3.73-3.78): (1/xi^2) d/dxi (xi^2 dtheta/dxi) = -theta^n,
// theta(0) = 1, theta'(0) = 0, solved here by RK4 (step 1e-4 in xi) from the series theta = 1 - xi^2/6
// + n xi^4/120 near the centre, up to the first zero xi_1 (or xi = 50 for n >= 5, whose radius is
// infinite). A polytrope of mass M and constant K (P = K rho^(1+1/n)) has rho = rho_c theta^n(r/alpha),
// alpha^2 = (n+1) K rho_c^(1/n - 1) / (4 pi G), R = alpha xi_1 and M = 4 pi alpha^3 rho_c (-xi^2 theta')_1.
#pragma once
#include <vector>

namespace sph::scenes {

class LaneEmden {
 public:
  explicit LaneEmden(double n);
  double n() const { return n_; }
  double xi1() const { return xi1_; }  ///< first zero (the surface)
  double theta(double xi) const;       ///< 0 beyond xi_1
  double dtheta(double xi) const;      ///< dtheta/dxi
  /// -xi^2 theta'(xi): the mass inside xi in units of 4 pi alpha^3 rho_c.
  double mass(double xi) const { return -xi * xi * dtheta(xi); }

 private:
  void at(double xi, double& t, double& dt) const;
  double n_, xi1_ = 0.0, dtheta1_ = 0.0, h_ = 1e-4;
  std::vector<double> theta_, dtheta_;
};

/// The polytrope of mass M, constant K and index n (n < 3) under gravity G: its alpha, rho_c, R.
struct PolytropeScales {
  double alpha, rho_c, R;
};
PolytropeScales polytrope_scales(const LaneEmden& le, double M, double K, double G);

/// The polytrope of index n, mass M and constant K under gravity G: its Lane-Emden solution and scales.
struct Polytrope {
  Polytrope(double n, double M, double K, double G) : le(n), scales(polytrope_scales(le, M, K, G)) {}
  double density(double r) const;  ///< rho_c theta^n(r / alpha) at radius r (0 beyond R)
  LaneEmden le;
  PolytropeScales scales;
};

}  // namespace sph::scenes
