// Kernel shapes as compile-time types (the pair-loop speed-ups of tests/bench/README.md): w(q) and dw/dq
// without sigma, for q >= 0, one struct per family (seed 000 eqs. 3.2.6-3.2.9; Wendland 1995). A pair
// loop templated on a shape evaluates it with no switch per pair; with_shape() picks the instantiation
// once per loop from a runtime kernel type. The B-splines are written as clamped powers, t = max(k - q,
// 0), which are exact (a clamped term adds +0) and need no branch on q; every shape is 0 at and beyond
// its support.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>

#include "sph/exp_poly.h"
#include "sph/params.h"

namespace sph::shape {

namespace detail {
inline double clamp0(double t) { return t > 0.0 ? t : 0.0; }
inline double pow3(double x) { return x * x * x; }
inline double pow4(double x) { return (x * x) * (x * x); }
inline double pow5(double x) { return pow4(x) * x; }
inline double pow6(double x) { return pow3(x) * pow3(x); }
}  // namespace detail

struct M4 {  // seed 000 eq. 3.2.7
  static constexpr double support = 2.0;
  double w(double q) const {
    const double t = detail::clamp0(2.0 - q), u = detail::clamp0(1.0 - q);
    return 0.25 * detail::pow3(t) - detail::pow3(u);
  }
  double dw(double q) const {
    const double t = detail::clamp0(2.0 - q), u = detail::clamp0(1.0 - q);
    return -0.75 * t * t + 3.0 * u * u;
  }
};

/// The B-splines of three clamped terms: a, b, c = max(K - q, 0), max(K - 1 - q, 0), max(K - 2 - q, 0)
/// with K the support, w = a^P - c1 b^P + c2 c^P and dw/dq = -P a^(P-1) + P c1 b^(P-1) - P c2 c^(P-1).
template <int P, int C1, int C2, int TwiceSupport>
struct ThreeTermSpline {
  static_assert(P == 4 || P == 5);
  static constexpr double support = TwiceSupport / 2.0;
  static double pow_p(double x) { return P == 4 ? detail::pow4(x) : detail::pow5(x); }
  static double pow_p1(double x) { return P == 4 ? detail::pow3(x) : detail::pow4(x); }
  double w(double q) const {
    const double a = detail::clamp0(support - q), b = detail::clamp0(support - 1.0 - q),
                 c = detail::clamp0(support - 2.0 - q);
    return pow_p(a) - double{C1} * pow_p(b) + double{C2} * pow_p(c);
  }
  double dw(double q) const {
    const double a = detail::clamp0(support - q), b = detail::clamp0(support - 1.0 - q),
                 c = detail::clamp0(support - 2.0 - q);
    return -double{P} * pow_p1(a) + double{P * C1} * pow_p1(b) - double{P * C2} * pow_p1(c);
  }
};

struct M5 : ThreeTermSpline<4, 5, 10, 5> {};  // seed 000 eq. 3.2.8

struct M6 : ThreeTermSpline<5, 6, 15, 6> {};  // seed 000 eq. 3.2.9

/// seed 000 eq. 3.2.6, truncated at q = 3 (the normalisation accounts for it). e^(-q^2) by exp_poly
/// (within 2 ulp of the library's exp), so the pair loops vectorise; its argument is clamped to the
/// support so that far candidates (masked to 0) never leave its range.
struct Gaussian {
  static constexpr double support = 3.0;
  double w(double q) const {
    const double e = exp_poly(-std::min(q * q, 9.0));
    return q < support ? e : 0.0;
  }
  double dw(double q) const {
    const double e = exp_poly(-std::min(q * q, 9.0));
    return q < support ? -2.0 * q * e : 0.0;
  }
};

/// Wendland C2 with support 2h (s = q/2): (1-s)^3 (1+3s) in 1D, (1-s)^4 (1+4s) in 2D and 3D.
struct WendlandC2 {
  static constexpr double support = 2.0;
  bool one_d = false;
  double w(double q) const {
    const double s = 0.5 * q, t = detail::clamp0(1.0 - s);
    return one_d ? detail::pow3(t) * (1.0 + 3.0 * s) : detail::pow4(t) * (1.0 + 4.0 * s);
  }
  double dw(double q) const {
    // d/dq = 0.5 d/ds; 1D: d/ds[(1-s)^3(1+3s)] = -12 s (1-s)^2; 2D/3D: d/ds[(1-s)^4(1+4s)] = -20 s (1-s)^3
    const double s = 0.5 * q, t = detail::clamp0(1.0 - s);
    return 0.5 * (one_d ? -12.0 * s * t * t : -20.0 * s * detail::pow3(t));
  }
};

/// Wendland C4 with support 2h: (1-s)^5 (1+5s+8s^2) in 1D, (1-s)^6 (1+6s+35/3 s^2) in 2D and 3D.
struct WendlandC4 {
  static constexpr double support = 2.0;
  bool one_d = false;
  double w(double q) const {
    const double s = 0.5 * q, t = detail::clamp0(1.0 - s);
    return one_d ? detail::pow5(t) * (1.0 + 5.0 * s + 8.0 * s * s)
                 : detail::pow6(t) * (1.0 + 6.0 * s + 35.0 / 3.0 * s * s);
  }
  double dw(double q) const {
    // 1D: d/ds = -14 s (1+4s) (1-s)^4; 2D/3D: d/ds = -56/3 s (1+5s) (1-s)^5
    const double s = 0.5 * q, t = detail::clamp0(1.0 - s);
    return 0.5 * (one_d ? -14.0 * s * (1.0 + 4.0 * s) * detail::pow4(t)
                        : -56.0 / 3.0 * s * (1.0 + 5.0 * s) * detail::pow5(t));
  }
};

/// Calls f(shape) with the shape object of `type` (Wendland shapes know whether dim == 1).
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_shape(KernelType type, int dim, F&& f) {
  switch (type) {
    case KernelType::M4: return std::forward<F>(f)(M4{});
    case KernelType::M5: return std::forward<F>(f)(M5{});
    case KernelType::M6: return std::forward<F>(f)(M6{});
    case KernelType::Gaussian: return std::forward<F>(f)(Gaussian{});
    case KernelType::WendlandC2: return std::forward<F>(f)(WendlandC2{dim == 1});
    case KernelType::WendlandC4: break;
  }
  return std::forward<F>(f)(WendlandC4{dim == 1});
}

}  // namespace sph::shape
