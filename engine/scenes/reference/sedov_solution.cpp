#include "reference/sedov_solution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph::scenes {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTable = 4000;  // intervals of the xi table

/// Surface of the unit sphere in dimension d: 2 (planar, both sides), 2 pi, 4 pi.
double unit_surface(int d) { return d == 1 ? 2.0 : d == 2 ? 2.0 * kPi : 4.0 * kPi; }

}  // namespace

SedovSolution::SedovSolution(int dim, double gamma) : dim_(dim), gamma_(gamma) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("SedovSolution: dim must be 1, 2 or 3");
  if (!(gamma > 1.0 && gamma < 2.0)) throw std::invalid_argument("SedovSolution: needs 1 < gamma < 2");
  const double j = dim, g = gamma, j2 = j + 2.0;
  // Kamm & Timmes 2007, eqs. (31)-(41) with omega = 0 (the "standard" case): the parameter V runs from
  // V0 = 2/((j+2) gamma) at the centre to V2 = 4/((j+2)(gamma+1)) at the shock, v = r V / t.
  a_ = j2 * (g + 1.0) / 4.0;
  b_ = (g + 1.0) / (g - 1.0);
  c_ = j2 * g / 2.0;
  d_ = j2 * (g + 1.0) / (j2 * (g + 1.0) - 2.0 * (2.0 + j * (g - 1.0)));
  e_ = (2.0 + j * (g - 1.0)) / 2.0;
  al0_ = 2.0 / j2;
  al2_ = -(g - 1.0) / (2.0 * (g - 1.0) + j);
  al1_ = j2 * g / (2.0 + j * (g - 1.0)) * (2.0 * j * (2.0 - g) / (g * j2 * j2) - al2_);
  al3_ = j / (2.0 * (g - 1.0) + j);
  al4_ = j2 / (2.0 - g) * al1_;
  al5_ = -2.0 / (2.0 - g);
  table_.resize(kTable + 1);
  for (int k = 0; k <= kTable; ++k) table_[k] = solve_xi(static_cast<double>(k) / kTable);
  // Energy integral. With U = 2R/((d+2) t), v2 = 2U/(gamma+1), rho2 = b rho1 and P2 = (gamma+1)/2 rho1 v2^2,
  // E = S_d int_0^R (rho v^2/2 + P/(gamma-1)) r^(d-1) dr
  //   = rho1 R^(d+2)/t^2 * S_d 16/((gamma+1)^2 (d+2)^2) int_0^1 (b f g^2/2 + (gamma+1) h/(2(gamma-1))) xi^(d-1) dxi.
  // Composite 5-point Gauss-Legendre on 400 panels, the profiles solved at each node (not the table).
  static const double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                   0.2369268850561891};
  constexpr int kPanels = 400;
  double integral = 0.0;
  for (int p = 0; p < kPanels; ++p) {
    const double lo = static_cast<double>(p) / kPanels, half = 0.5 / kPanels;
    for (int q = 0; q < 5; ++q) {
      const Shape s = solve_xi(lo + half * (1.0 + node[q]));
      const double density = 0.5 * b_ * s.f * s.g * s.g + (g + 1.0) / (2.0 * (g - 1.0)) * s.h;
      integral += weight[q] * half * density * std::pow(s.xi, j - 1.0);
    }
  }
  alpha_ = unit_surface(dim) * 16.0 / ((g + 1.0) * (g + 1.0) * j2 * j2) * integral;
  xi0_ = std::pow(alpha_, -1.0 / j2);
}

SedovSolution::Shape SedovSolution::at_parameter(double y) const {
  // y = x2 = b (c V - 1), so V = (1 + y/b)/c; Kamm & Timmes eqs. (42)-(45), omega = 0
  const double V = (1.0 + y / b_) / c_;
  const double x1 = a_ * V, x2 = y, x3 = d_ * (1.0 - e_ * V), x4 = b_ * (1.0 - c_ * V / gamma_);
  Shape s;
  s.xi = std::pow(x1, -al0_) * std::pow(x2, -al2_) * std::pow(x3, -al1_);
  s.f = std::pow(x2, al3_) * std::pow(x3, al4_) * std::pow(x4, al5_);
  s.g = x1 * s.xi;
  s.h = std::pow(x1, al0_ * dim_) * std::pow(x3, al4_ - 2.0 * al1_) * std::pow(x4, 1.0 + al5_);
  return s;
}

SedovSolution::Shape SedovSolution::solve_xi(double xi) const {
  if (xi >= 1.0) return at_parameter(1.0);
  if (xi <= 0.0) {  // the centre: rho -> 0, v -> 0, P -> its finite limit (no x2 in P/P2)
    Shape s = at_parameter(1e-300);
    s.xi = 0.0;
    s.f = 0.0;
    s.g = 0.0;
    return s;
  }
  // xi grows monotonically with y; xi ~ y^(-alpha2) near the centre, so bisect in log y
  double lo = std::log(1e-300), hi = 0.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (at_parameter(std::exp(mid)).xi < xi ? lo : hi) = mid;
  }
  Shape s = at_parameter(std::exp(0.5 * (lo + hi)));
  s.xi = xi;
  return s;
}

SedovSolution::Shape SedovSolution::at_xi(double xi) const {
  if (xi <= 0.0) return table_.front();
  if (xi >= 1.0) return table_.back();
  const double pos = xi * kTable;
  const auto k = std::min(static_cast<std::size_t>(pos), static_cast<std::size_t>(kTable - 1));
  const double w = pos - static_cast<double>(k);
  const Shape& p = table_[k];
  const Shape& q = table_[k + 1];
  return {xi, p.f + w * (q.f - p.f), p.g + w * (q.g - p.g), p.h + w * (q.h - p.h)};
}

double SedovSolution::shock_radius(double E, double rho1, double t) const {
  return xi0_ * std::pow(E * t * t / rho1, 1.0 / (dim_ + 2.0));
}

SedovSolution::State SedovSolution::state(double r, double t, double E, double rho1) const {
  const double R = shock_radius(E, rho1, t);
  if (r >= R) return {rho1, 0.0, 0.0};
  const double U = 2.0 * R / ((dim_ + 2.0) * t);  // dR/dt
  const double v2 = 2.0 * U / (gamma_ + 1.0);
  const Shape s = at_xi(r / R);
  return {b_ * rho1 * s.f, v2 * s.g, 0.5 * (gamma_ + 1.0) * rho1 * v2 * v2 * s.h};
}

}  // namespace sph::scenes
