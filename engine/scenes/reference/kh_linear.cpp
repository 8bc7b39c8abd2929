// Shooting for the linear Kelvin-Helmholtz eigenvalue (see kh_linear.h).
#include "kh_linear.h"

#include <cmath>

namespace sph::scenes {
namespace {

using C = std::complex<double>;

/// Decay exponent outside the layer: lambda^2 = k^2 + rho Omega^2 / (gamma P), Re lambda > 0.
C lambda(double k, double rho, C omega, double gP) {
  C l = std::sqrt(k * k + rho * omega * omega / gP);
  return l.real() < 0.0 ? -l : l;
}

/// v/p at y_mid of the solution that decays away from the layer on the side of y_end (integrated from
/// y_end towards the layer, the direction in which it grows, so the other solution cannot swamp it).
C ratio_at(const ShearLayer& L, double k, C s, double y_end, double y_mid, int steps) {
  const double gP = L.gamma * L.P;
  const C ik(0.0, k);
  auto rhs = [&](double y, C p, C v, C& dp, C& dv) {
    const double rho = L.rho(y);
    const C om = s + ik * L.U(y);
    dp = -rho * om * v;
    dv = -(om / gP + k * k / (rho * om)) * p + ik * L.dUdy(y) * v / om;
  };
  const double r0 = L.rho(y_end);
  const C om0 = s + ik * L.U(y_end);
  const double side = y_end < y_mid ? 1.0 : -1.0;  // below: p ~ exp(+lambda y); above: exp(-lambda y)
  C p = 1.0, v = -side * lambda(k, r0, om0, gP) / (r0 * om0);
  const double h = (y_mid - y_end) / steps;
  for (int i = 0; i < steps; ++i) {
    const double y = y_end + i * h;
    C k1p, k1v, k2p, k2v, k3p, k3v, k4p, k4v;
    rhs(y, p, v, k1p, k1v);
    rhs(y + 0.5 * h, p + 0.5 * h * k1p, v + 0.5 * h * k1v, k2p, k2v);
    rhs(y + 0.5 * h, p + 0.5 * h * k2p, v + 0.5 * h * k2v, k3p, k3v);
    rhs(y + h, p + h * k3p, v + h * k3v, k4p, k4v);
    p += h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    const double scale = std::abs(p) + std::abs(v);  // linear: renormalise against overflow
    p /= scale;
    v /= scale;
  }
  return v / p;
}

/// Zero at an eigenvalue: the two decaying solutions have the same v/p at the layer's middle (p and
/// v = Omega xi are continuous there). Made dimensionless by the far-field k/(rho Omega) of one side.
C mismatch(const ShearLayer& L, double k, C s, int steps) {
  const double ym = 0.5 * (L.y_lo + L.y_hi);
  const C scale = k / (L.rho(L.y_lo) * (s + C(0.0, k) * L.U(L.y_lo)));
  return (ratio_at(L, k, s, L.y_lo, ym, steps / 2) - ratio_at(L, k, s, L.y_hi, ym, steps / 2)) / scale;
}

}  // namespace

double kh_vortex_sheet_rate(double k, double rho1, double rho2, double dU) {
  return k * std::abs(dU) * std::sqrt(rho1 * rho2) / (rho1 + rho2);
}

KhMode kh_linear_mode(const ShearLayer& L, double k, int steps) {
  const double r1 = L.rho(L.y_lo), r2 = L.rho(L.y_hi), u1 = L.U(L.y_lo), u2 = L.U(L.y_hi);
  // the vortex sheet: growth sigma, phase speed the density-weighted mean velocity (s = sigma - i k c)
  const double c = (r1 * u1 + r2 * u2) / (r1 + r2);
  C s0(kh_vortex_sheet_rate(k, r1, r2, u2 - u1), -k * c);
  C s1 = s0 * 0.9;
  C f0 = mismatch(L, k, s0, steps), f1 = mismatch(L, k, s1, steps);
  KhMode out;
  for (int it = 1; it <= 60; ++it) {
    if (f1 == f0) break;
    C s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    if (s2.real() <= 0.0) s2 = C(0.5 * s1.real(), s2.imag());  // stay on the growing branch
    s0 = s1;
    f0 = f1;
    s1 = s2;
    f1 = mismatch(L, k, s1, steps);
    out.iterations = it;
    if (std::abs(s1 - s0) < 1e-12 * std::abs(s1)) {
      out.converged = true;
      break;
    }
  }
  out.s = s1;
  return out;
}

}  // namespace sph::scenes
