// Exact Riemann solver for the 1D Euler equations, ideal gas p = (gamma-1) rho e.
//
// Follows the construction of seed 003 eqs. 3.20-3.51 (Castellanos 2010, exact shock-tube
// solution) and Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", ch. 4:
//   - the star pressure p* is the root of f(p) = f_L(p) + f_R(p) + (v_R - v_L) (Toro sec. 4.2),
//     where f_K is the shock branch (p > p_K) or rarefaction branch (p <= p_K) of wave K;
//   - p* is found by Newton iteration from the two-rarefaction, PVRS or two-shock guess
//     (Toro sec. 4.3), safeguarded by a bracket so that iterates stay positive, to relative
//     change 1e-14;
//   - v* = (v_L + v_R)/2 + (f_R(p*) - f_L(p*))/2;
//   - the solution depends on x and t only through s = (x - x0)/t and is sampled wave by
//     wave (Toro sec. 4.5): left wave, contact at s = v*, right wave.
// All quantities are in the caller's consistent code units (density, velocity, pressure;
// specific internal energy in velocity^2). Nothing is stored outside the solver object.
#include "sph/riemann.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sph {
namespace {

// Value and derivative df/dp of the one-wave pressure function f_K(p) (Toro sec. 4.2).
struct WaveFunction { double f, df; };

WaveFunction wave_function(double p, const GasState& k, double c, double g) {
  if (p > k.p) {
    // Shock: Rankine-Hugoniot relation between the K state and the star state.
    const double a = 2.0 / ((g + 1.0) * k.rho);
    const double b = (g - 1.0) / (g + 1.0) * k.p;
    const double q = std::sqrt(a / (p + b));
    return {(p - k.p) * q, q * (1.0 - 0.5 * (p - k.p) / (p + b))};
  }
  // Rarefaction: isentropic, generalised Riemann invariant v +- 2c/(gamma-1) carried across.
  const double z = (g - 1.0) / (2.0 * g);
  const double ratio = p / k.p;
  return {2.0 * c / (g - 1.0) * (std::pow(ratio, z) - 1.0),
          std::pow(ratio, -(g + 1.0) / (2.0 * g)) / (k.rho * c)};
}

// Density behind wave K at star pressure ps: Hugoniot for a shock, isentrope for a fan.
double star_density(double ps, const GasState& k, double g) {
  const double ratio = ps / k.p;
  if (ratio > 1.0) {
    const double m = (g - 1.0) / (g + 1.0);
    return k.rho * (ratio + m) / (m * ratio + 1.0);
  }
  return k.rho * std::pow(ratio, 1.0 / g);
}

// Speed of a shock into state K: dir = -1 for the left wave, +1 for the right wave.
double shock_speed(double ps, const GasState& k, double c, double g, double dir) {
  return k.v + dir * c * std::sqrt((g + 1.0) / (2.0 * g) * ps / k.p + (g - 1.0) / (2.0 * g));
}

// State inside a rarefaction fan at s; dir = -1 for the left fan, +1 for the right fan.
GasState fan_state(double s, const GasState& k, double c, double g, double dir) {
  const double base = 2.0 / (g + 1.0) - dir * (g - 1.0) / ((g + 1.0) * c) * (k.v - s);
  return {k.rho * std::pow(base, 2.0 / (g - 1.0)),
          2.0 / (g + 1.0) * (-dir * c + 0.5 * (g - 1.0) * k.v + s),
          k.p * std::pow(base, 2.0 * g / (g - 1.0))};
}

// Two-shock weight g_K(p) = sqrt(A_K / (p + B_K)) of the two-shock approximation (Toro sec. 4.3).
double two_shock_weight(double p, const GasState& k, double g) {
  return std::sqrt(2.0 / ((g + 1.0) * k.rho) / (p + (g - 1.0) / (g + 1.0) * k.p));
}

// Root p* of f(p) = f_L(p) + f_R(p) + (v_R - v_L) to relative change 1e-14; counts the
// Newton iterations. Throws std::invalid_argument if p* underflows (near vacuum).
double star_pressure(const GasState& l, const GasState& r, double cl, double cr, double g,
                     int& iterations) {
  const double dv = r.v - l.v;
  auto f = [&](double p) {
    const WaveFunction wl = wave_function(p, l, cl, g), wr = wave_function(p, r, cr, g);
    return WaveFunction{wl.f + wr.f + dv, wl.df + wr.df};
  };

  // f is increasing and concave in p, so Newton started below p* climbs monotonically onto it;
  // from above it may overshoot, possibly below zero, and is then replaced by bisection of the
  // bracket [lo, hi] (f(lo) < 0 < f(hi)). Below p_min = min(p_L, p_R) both waves are fans and
  // f equals the two-rarefaction function, whose root is known in closed form (Toro sec. 4.3).
  const double p_min = std::min(l.p, r.p), p_max = std::max(l.p, r.p);
  double lo = 0.0, hi = std::numeric_limits<double>::infinity(), p = 0.0;
  if (f(p_min).f >= 0.0) {
    const double z = (g - 1.0) / (2.0 * g);
    const double num = cl + cr - 0.5 * (g - 1.0) * dv;  // > 0: no vacuum
    const double den = cl / std::pow(l.p, z) + cr / std::pow(r.p, z);
    p = std::pow(num / den, 1.0 / z);  // two-rarefaction value, exact up to rounding
    if (!(p > 0.0))  // p* underflows: the fans all but empty the star region
      throw std::invalid_argument("RiemannSolver: initial data generate a (near) vacuum");
    hi = p_min;
  } else {
    // Primitive-variable (PVRS) guess when the data are nearly uniform, else the two-shock
    // approximation evaluated at the PVRS pressure (Toro sec. 4.3); never below the bracket.
    const double p_pv =
        std::max(0.0, 0.5 * (l.p + r.p) - 0.125 * dv * (l.rho + r.rho) * (cl + cr));
    if (p_max <= 2.0 * p_min && p_pv >= p_min && p_pv <= p_max) {
      p = p_pv;
    } else {
      const double gl = two_shock_weight(p_pv, l, g), gr = two_shock_weight(p_pv, r, g);
      p = (gl * l.p + gr * r.p - dv) / (gl + gr);
    }
    lo = p_min;
    if (!(p > lo)) p = lo;
  }

  constexpr double kTol = 1e-14;  // relative change of p* between iterates
  constexpr int kMaxIter = 200;
  int iter = 0;
  for (; iter < kMaxIter; ++iter) {
    const WaveFunction w = f(p);
    if (w.f == 0.0) break;
    (w.f < 0.0 ? lo : hi) = p;
    double next = p - w.f / w.df;
    // The bracket is closed so that a converged step rounding onto an end point is accepted.
    // Bisection is geometric once lo > 0: the bracket may span many decades.
    if (!(next >= lo && next <= hi)) {
      if (!std::isfinite(hi)) next = 2.0 * lo;
      else next = lo > 0.0 ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * hi;
    }
    if (!(next > 0.0))  // p* below the smallest double: the star region is all but empty
      throw std::invalid_argument("RiemannSolver: initial data generate a (near) vacuum");
    const double change = 2.0 * std::abs(next - p) / (next + p);
    // Returning to the other, already evaluated end of the bracket means f is at its rounding
    // limit (only for ill-conditioned, near-vacuum data): p* is pinned to within the bracket.
    const bool cycling = next != p && (next == lo || next == hi);
    p = next;
    if (change < kTol || cycling) break;
  }
  if (iter == kMaxIter) throw std::runtime_error("RiemannSolver: p* did not converge");
  iterations = iter + 1;
  return p;
}

bool valid_state(const GasState& s) {
  return std::isfinite(s.rho) && std::isfinite(s.v) && std::isfinite(s.p) && s.rho > 0.0 &&
         s.p > 0.0;
}

}  // namespace

RiemannSolver::RiemannSolver(GasState left, GasState right, double gamma, double x0)
    : left_(left), right_(right), gamma_(gamma), x0_(x0) {
  if (!valid_state(left) || !valid_state(right))
    throw std::invalid_argument("RiemannSolver: rho and p must be finite and positive");
  if (!std::isfinite(gamma) || gamma <= 1.0)
    throw std::invalid_argument("RiemannSolver: gamma must be > 1");
  if (!std::isfinite(x0)) throw std::invalid_argument("RiemannSolver: x0 must be finite");

  const double g = gamma_;
  c_left_ = std::sqrt(g * left_.p / left_.rho);
  c_right_ = std::sqrt(g * right_.p / right_.rho);
  const double dv = right_.v - left_.v;
  // Pressure positivity condition (Toro sec. 4.6): otherwise the two fans leave a vacuum.
  if (2.0 / (g - 1.0) * (c_left_ + c_right_) <= dv)
    throw std::invalid_argument("RiemannSolver: initial data generate a vacuum");

  int iterations = 0;
  const double p = star_pressure(left_, right_, c_left_, c_right_, g, iterations);
  const double fl = wave_function(p, left_, c_left_, g).f;
  const double fr = wave_function(p, right_, c_right_, g).f;
  star_ = {p, 0.5 * (left_.v + right_.v) + 0.5 * (fr - fl), iterations};
  rho_star_left_ = star_density(p, left_, g);
  rho_star_right_ = star_density(p, right_, g);
}

RiemannStar RiemannSolver::star() const { return star_; }

double RiemannSolver::gamma() const { return gamma_; }

WaveSpan RiemannSolver::span() const {
  const double g = gamma_, ps = star_.p;
  const double lo = ps > left_.p ? shock_speed(ps, left_, c_left_, g, -1.0) : left_.v - c_left_;
  const double hi = ps > right_.p ? shock_speed(ps, right_, c_right_, g, 1.0) : right_.v + c_right_;
  return {lo, hi};
}

GasState RiemannSolver::sample(double x, double t) const {
  if (!(t >= 0.0)) throw std::invalid_argument("RiemannSolver::sample: t must be >= 0");
  if (t == 0.0) return x < x0_ ? left_ : right_;
  return sample_speed((x - x0_) / t);
}

double RiemannSolver::internal_energy(double x, double t) const {
  const GasState s = sample(x, t);
  return s.p / ((gamma_ - 1.0) * s.rho);
}

// Wave-by-wave sampling of the self-similar solution (Toro sec. 4.5), s = (x - x0)/t.
GasState RiemannSolver::sample_speed(double s) const {
  const double g = gamma_;
  const double ps = star_.p, vs = star_.v;
  const bool on_left = s <= vs;  // which side of the contact discontinuity
  const GasState& k = on_left ? left_ : right_;
  const double c = on_left ? c_left_ : c_right_;
  const double dir = on_left ? -1.0 : 1.0;  // outward direction of wave K
  const GasState star_k{on_left ? rho_star_left_ : rho_star_right_, vs, ps};

  // Position measured outward from the contact: the K state lies beyond the outermost edge.
  auto outside = [&](double edge) { return dir * (s - edge) >= 0.0; };
  if (ps > k.p) {
    return outside(shock_speed(ps, k, c, g, dir)) ? k : star_k;
  }
  const double head = k.v + dir * c;                              // fan edge next to K
  const double tail = vs + dir * std::sqrt(g * ps / star_k.rho);  // fan edge next to star
  if (outside(head)) return k;
  if (!outside(tail)) return star_k;
  return fan_state(s, k, c, g, dir);
}

}  // namespace sph
