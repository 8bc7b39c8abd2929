// Exact Burgers solutions from the ramp (see reference/burgers_exact.h). Cole-Hopf: with
// u = -2 eps phi_x / phi, phi_t = eps phi_xx and phi(x, 0) = exp(-U0(x) / (2 eps)); the heat kernel gives
// phi ~ int exp(-E(y) / (2 eps)) dy and u = int ((x - y)/t) exp(-E/(2 eps)) / int exp(-E/(2 eps)).
// Each piece of E is written about its own minimiser r on the piece as E - E_min = e + c1 s + c2 s^2,
// s = y - r, and grows away from r within the piece, so that the quadrature window is one interval
// per piece found in closed form, and the integrand is evaluated in s (no cancellation for small t).
#include "reference/burgers_exact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace sph::scenes {
namespace {

constexpr int kNodes = 20;
constexpr double kWindow = 50.0;    // the window keeps G >= e^-50 (relative to its largest value, 1)
constexpr double kVariation = 8.0;  // largest change of the exponent across one sub-interval

struct GaussLegendre {
  std::array<double, kNodes> x, w;
};

// nodes and weights on [-1, 1]: Newton on the Legendre polynomial P_n from Chebyshev-like guesses
GaussLegendre make_gauss_legendre() {
  GaussLegendre g{};
  for (int i = 0; i < kNodes; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (kNodes + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;  // P_0, P_1, then the three-term recurrence up to P_n
      for (int k = 2; k <= kNodes; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = kNodes * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    g.x[i] = z;
    g.w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
  return g;
}

const GaussLegendre& gauss_legendre() {
  static const GaussLegendre g = make_gauss_legendre();
  return g;
}

// One piece of the exponent on [lo, hi]: E(y) = E_r + c1 s + c2 s^2, s = y - r, r the piece's minimiser,
// xr = x - r (kept exactly where r is a vertex); e = E_r - E_min once E_min is known.
struct Piece {
  double lo, hi, r, xr, Er, c1, c2, e = 0.0;
};

// int over the piece's window of G and of ((x - y)/t) G
void integrate(const Piece& p, double t, double eps, double& D, double& N) {
  const double two_eps = 2.0 * eps, T = two_eps * kWindow;
  if (!(p.e < T)) return;
  const double room = T - p.e;  // > 0, so that a rising parabola always crosses: finite windows
  // the window [r + sl, r + sr]: the first crossings of e + c1 s + c2 s^2 = T on either side of r (stable
  // root formula; no crossing within the parabola's rising part means the window reaches the piece end)
  auto reach = [&](double slope) {
    const double disc = slope * slope + 4.0 * p.c2 * room;
    if (disc < 0.0) return std::numeric_limits<double>::infinity();
    const double den = slope + std::sqrt(disc);
    return den > 0.0 ? 2.0 * room / den : std::numeric_limits<double>::infinity();
  };
  const double sl = p.lo < p.r ? std::max(p.lo - p.r, -reach(-p.c1)) : 0.0;
  const double sr = p.hi > p.r ? std::min(p.hi - p.r, reach(p.c1)) : 0.0;
  if (!(sr > sl)) return;
  auto dphi = [&](double s) { return std::abs(p.c1 + 2.0 * p.c2 * s) / two_eps; };
  const double change = (sr - sl) * std::max(dphi(sl), dphi(sr)) / kVariation;
  const int n = static_cast<int>(std::clamp(std::ceil(change), 1.0, 1e5));
  const double len = (sr - sl) / n;
  const GaussLegendre& g = gauss_legendre();
  for (int k = 0; k < n; ++k) {
    const double half = 0.5 * len, mid = sl + (k + 0.5) * len;
    for (int i = 0; i < kNodes; ++i) {
      const double s = mid + half * g.x[i];
      const double G = std::exp(-(p.e + p.c1 * s + p.c2 * s * s) / two_eps) * half * g.w[i];
      D += G;
      N += G * (p.xr - s) / t;
    }
  }
}

}  // namespace

double burgers_initial(double x, double a) {
  if (x <= 0.0) return 1.0;
  if (x < a) return 1.0 - x / a;
  return 0.0;
}

double burgers_inviscid(double x, double t, double a) {
  a = std::max(a, 0.0);
  if (t <= 0.0) return burgers_initial(x, a);
  if (t < a) {  // seed 002 eq. 22: the characteristics from the ramp meet at (a, a)
    if (x <= t) return 1.0;
    if (x < a) return (a - x) / (a - t);
    return 0.0;
  }
  const double xs = a + 0.5 * (t - a);  // Rankine-Hugoniot: s = (u_l + u_r)/2 = 1/2
  if (x < xs) return 1.0;
  if (x > xs) return 0.0;
  return 0.5;
}

double burgers_viscous(double x, double t, double a, double eps) {
  a = std::max(a, 0.0);
  if (t <= 0.0) return burgers_initial(x, a);
  if (!(eps > 0.0)) return burgers_inviscid(x, t, a);
  const double inf = std::numeric_limits<double>::infinity();
  std::array<Piece, 4> pieces;  // no allocation: at most four pieces
  int n = 0;
  auto add = [&](const Piece& p) { pieces[n++] = p; };
  // y < 0: U0 = y, E = (y - y1)^2/(2t) + x - t/2 with y1 = x - t (the characteristic from the left state)
  {
    const double y1 = x - t;
    const double r = std::min(y1, 0.0);
    add({-inf, 0.0, r, r == y1 ? t : x, (r - y1) * (r - y1) / (2 * t) + x - 0.5 * t, (r - y1) / t, 1.0 / (2 * t)});
  }
  // y > a: U0 = a/2, E = (y - x)^2/(2t) + a/2
  {
    const double r = std::max(x, a);
    add({a, inf, r, r == x ? 0.0 : x - a, (r - x) * (r - x) / (2 * t) + 0.5 * a, (r - x) / t, 1.0 / (2 * t)});
  }
  // 0 < y < a: U0 = y - y^2/(2a), E = (x - y)^2/(2t) + U0, E'' = 2 c2 = (a - t)/(a t)
  if (a > 0.0) {
    const double c2 = (a - t) / (2 * a * t);
    auto E = [&](double y) { return (x - y) * (x - y) / (2 * t) + y - y * y / (2 * a); };
    auto dE = [&](double y) { return (y - x) / t + 1.0 - y / a; };
    auto about = [&](double lo, double hi, double r) { add({lo, hi, r, x - r, E(r), dE(r), c2}); };
    if (c2 > 0.0) {  // t < a: convex, the vertex is the foot of the characteristic through x
      const double yv = a * (x - t) / (a - t);
      if (yv > 0.0 && yv < a)
        add({0.0, a, yv, t * (a - x) / (a - t), 0.5 * t * (1 - yv / a) * (1 - yv / a) + yv - yv * yv / (2 * a), 0.0,
             c2});
      else
        about(0.0, a, yv <= 0.0 ? 0.0 : a);
    } else if (c2 < 0.0) {  // t > a: concave, split at the maximum; each half has its minimum at its end
      const double ym = std::clamp(a * (x - t) / (a - t), 0.0, a);
      if (ym > 0.0) about(0.0, ym, 0.0);
      if (ym < a) about(ym, a, a);
    } else {  // t = a: linear
      about(0.0, a, dE(0.0) >= 0.0 ? 0.0 : a);
    }
  }
  double Emin = inf;
  for (int k = 0; k < n; ++k) Emin = std::min(Emin, pieces[k].Er);
  double D = 0.0, N = 0.0;
  for (int k = 0; k < n; ++k) {
    pieces[k].e = pieces[k].Er - Emin;
    integrate(pieces[k], t, eps, D, N);
  }
  return N / D;
}

double seed_error(std::span<const double> x, std::span<const double> u, const std::function<double(double)>& exact) {
  if (x.size() != u.size()) throw std::invalid_argument("seed_error: x and u differ in length");
  if (x.size() < 2) return 0.0;
  std::vector<double> xs(x.begin(), x.end());
  std::sort(xs.begin(), xs.end());
  double hmax = 0.0;
  for (std::size_t i = 1; i < xs.size(); ++i) hmax = std::max(hmax, xs[i] - xs[i - 1]);
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) sum += std::abs(u[i] - exact(x[i]));
  return hmax * sum;  // seed 002 §4.3
}

}  // namespace sph::scenes
