#include "reference/lane_emden.h"

#include <cmath>
#include <numbers>

namespace sph::scenes {

LaneEmden::LaneEmden(double n) : n_(n) {
  const double xi_max = 50.0;
  auto power = [&](double t) { return t > 0.0 ? std::pow(t, n_) : 0.0; };
  // y = (theta, theta'); y'' = -theta^n - (2/xi) theta'
  auto rhs = [&](double xi, double t, double dt, double& ft, double& fdt) {
    ft = dt;
    fdt = -power(t) - 2.0 / xi * dt;
  };
  double xi = h_, t = 1.0 - xi * xi / 6.0 + n_ * std::pow(xi, 4) / 120.0, dt = -xi / 3.0 + n_ * std::pow(xi, 3) / 30.0;
  theta_ = {1.0, t};
  dtheta_ = {0.0, dt};
  while (xi < xi_max) {
    double k1t, k1d, k2t, k2d, k3t, k3d, k4t, k4d;
    rhs(xi, t, dt, k1t, k1d);
    rhs(xi + 0.5 * h_, t + 0.5 * h_ * k1t, dt + 0.5 * h_ * k1d, k2t, k2d);
    rhs(xi + 0.5 * h_, t + 0.5 * h_ * k2t, dt + 0.5 * h_ * k2d, k3t, k3d);
    rhs(xi + h_, t + h_ * k3t, dt + h_ * k3d, k4t, k4d);
    const double tn = t + h_ / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t);
    const double dn = dt + h_ / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d);
    if (tn <= 0.0) {  // the surface inside this step: linear interpolation of the zero
      xi1_ = xi + h_ * t / (t - tn);
      // theta' at the surface: one RK4 step of the (short) remaining length from the last point inside
      const double w = xi1_ - xi;
      rhs(xi, t, dt, k1t, k1d);
      rhs(xi + 0.5 * w, t + 0.5 * w * k1t, dt + 0.5 * w * k1d, k2t, k2d);
      rhs(xi + 0.5 * w, t + 0.5 * w * k2t, dt + 0.5 * w * k2d, k3t, k3d);
      rhs(xi + w, t + w * k3t, dt + w * k3d, k4t, k4d);
      dtheta1_ = dt + w / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d);
      return;
    }
    xi += h_;
    t = tn;
    dt = dn;
    theta_.push_back(t);
    dtheta_.push_back(dt);
  }
  xi1_ = xi;  // n >= 5: no zero before xi_max
  dtheta1_ = dt;
}

void LaneEmden::at(double xi, double& t, double& dt) const {
  // cubic Hermite in theta with the stored slopes (accurate to the RK4 solution's own error), linear in
  // theta'; the last interval ends at the surface xi_1 (theta = 0)
  std::size_t k = static_cast<std::size_t>(xi / h_);
  const std::size_t last = theta_.size() - 1;
  double x0, x1, t0, t1, d0, d1;
  if (k < last) {
    x0 = h_ * static_cast<double>(k); x1 = x0 + h_;
    t0 = theta_[k]; t1 = theta_[k + 1]; d0 = dtheta_[k]; d1 = dtheta_[k + 1];
  } else {
    k = last;
    x0 = h_ * static_cast<double>(k); x1 = xi1_;
    t0 = theta_[k]; t1 = 0.0; d0 = dtheta_[k]; d1 = dtheta1_;
  }
  const double w = x1 - x0, u = w > 0.0 ? (xi - x0) / w : 0.0, u2 = u * u, u3 = u2 * u;
  t = (2 * u3 - 3 * u2 + 1) * t0 + (u3 - 2 * u2 + u) * w * d0 + (-2 * u3 + 3 * u2) * t1 + (u3 - u2) * w * d1;
  dt = d0 + u * (d1 - d0);
}

double LaneEmden::theta(double xi) const {
  if (xi >= xi1_) return 0.0;
  double t, dt;
  at(xi, t, dt);
  return t;
}

double LaneEmden::dtheta(double xi) const {
  if (xi >= xi1_) return dtheta1_;
  double t, dt;
  at(xi, t, dt);
  return dt;
}

PolytropeScales polytrope_scales(const LaneEmden& le, double M, double K, double G) {
  // alpha^3 rho_c = M / (4 pi m1) and alpha^2 = c K rho_c^((1-n)/n), c = (n+1)/(4 pi G):
  // rho_c^((3-n)/(2n)) = M / (4 pi m1 (c K)^(3/2))
  const double n = le.n(), m1 = le.mass(le.xi1()), c = (n + 1.0) / (4.0 * std::numbers::pi * G);
  const double rho_c = std::pow(M / (4.0 * std::numbers::pi * m1 * std::pow(c * K, 1.5)), 2.0 * n / (3.0 - n));
  const double alpha = std::sqrt(c * K * std::pow(rho_c, (1.0 - n) / n));
  return {alpha, rho_c, alpha * le.xi1()};
}

double Polytrope::density(double r) const { return scales.rho_c * std::pow(le.theta(r / scales.alpha), le.n()); }

}  // namespace sph::scenes
