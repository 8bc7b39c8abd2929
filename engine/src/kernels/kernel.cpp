// Kernel shapes and normalisations (seed 000 eqs. 3.2.6–3.2.11; Wendland 1995; Dehnen & Aly 2012, MNRAS 425, 1068).
#include "sph/kernel.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph {
namespace {

constexpr double pi = std::numbers::pi;

double pow3(double x) { return x * x * x; }
double pow4(double x) { return (x * x) * (x * x); }
double pow5(double x) { return pow4(x) * x; }
double pow6(double x) { return pow3(x) * pow3(x); }

}  // namespace

Kernel::Kernel(KernelType type, int dim) : type_(type), dim_(dim) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("kernel dimension must be 1, 2 or 3");
  const int i = dim - 1;
  switch (type) {
    case KernelType::M4: {  // seed 000 eq. 3.2.7: support 2h, sigma = [2/3, 10/(7 pi), 1/pi]
      const double s[3] = {2.0 / 3.0, 10.0 / (7.0 * pi), 1.0 / pi};
      support_ = 2.0;
      sigma_ = s[i];
      break;
    }
    case KernelType::M5: {  // seed 000 eq. 3.2.8: support 2.5h, sigma = [1/24, 96/(1199 pi), 1/(20 pi)]
      const double s[3] = {1.0 / 24.0, 96.0 / (1199.0 * pi), 1.0 / (20.0 * pi)};
      support_ = 2.5;
      sigma_ = s[i];
      break;
    }
    case KernelType::M6: {  // seed 000 eq. 3.2.9: support 3h, sigma = [1/120, 7/(478 pi), 1/(120 pi)]
      const double s[3] = {1.0 / 120.0, 7.0 / (478.0 * pi), 1.0 / (120.0 * pi)};
      support_ = 3.0;
      sigma_ = s[i];
      break;
    }
    case KernelType::Gaussian: {
      // seed 000 eq. 3.2.6, truncated at q = 3 and renormalised so the truncated kernel integrates to 1.
      const double e9 = std::exp(-9.0), erf3 = std::erf(3.0);
      const double integral[3] = {std::sqrt(pi) * erf3, pi * (1.0 - e9),
                                  4.0 * pi * (std::sqrt(pi) / 4.0 * erf3 - 1.5 * e9)};
      support_ = 3.0;
      sigma_ = 1.0 / integral[i];
      break;
    }
    case KernelType::WendlandC2: {
      // Support H = 2h; sigma for unit support (Dehnen & Aly 2012, Table 1) divided by 2^d.
      const double s[3] = {5.0 / 4.0, 7.0 / pi, 21.0 / (2.0 * pi)};
      support_ = 2.0;
      sigma_ = s[i] / std::pow(2.0, dim);
      break;
    }
    case KernelType::WendlandC4: {
      const double s[3] = {3.0 / 2.0, 9.0 / pi, 495.0 / (32.0 * pi)};
      support_ = 2.0;
      sigma_ = s[i] / std::pow(2.0, dim);
      break;
    }
  }
}

double Kernel::w(double q) const {
  if (q >= support_) return 0.0;
  switch (type_) {
    case KernelType::M4:  // seed 000 eq. 3.2.7
      return q < 1.0 ? 0.25 * pow3(2.0 - q) - pow3(1.0 - q) : 0.25 * pow3(2.0 - q);
    case KernelType::M5: {  // seed 000 eq. 3.2.8
      double r = pow4(2.5 - q);
      if (q < 1.5) r -= 5.0 * pow4(1.5 - q);
      if (q < 0.5) r += 10.0 * pow4(0.5 - q);
      return r;
    }
    case KernelType::M6: {  // seed 000 eq. 3.2.9
      double r = pow5(3.0 - q);
      if (q < 2.0) r -= 6.0 * pow5(2.0 - q);
      if (q < 1.0) r += 15.0 * pow5(1.0 - q);
      return r;
    }
    case KernelType::Gaussian:  // seed 000 eq. 3.2.6
      return std::exp(-q * q);
    case KernelType::WendlandC2: {
      const double s = 0.5 * q;
      return dim_ == 1 ? pow3(1.0 - s) * (1.0 + 3.0 * s) : pow4(1.0 - s) * (1.0 + 4.0 * s);
    }
    case KernelType::WendlandC4: {
      const double s = 0.5 * q;
      return dim_ == 1 ? pow5(1.0 - s) * (1.0 + 5.0 * s + 8.0 * s * s)
                       : pow6(1.0 - s) * (1.0 + 6.0 * s + 35.0 / 3.0 * s * s);
    }
  }
  return 0.0;
}

double Kernel::dw(double q) const {
  if (q >= support_) return 0.0;
  switch (type_) {
    case KernelType::M4:
      return q < 1.0 ? -0.75 * (2.0 - q) * (2.0 - q) + 3.0 * (1.0 - q) * (1.0 - q)
                     : -0.75 * (2.0 - q) * (2.0 - q);
    case KernelType::M5: {
      double r = -4.0 * pow3(2.5 - q);
      if (q < 1.5) r += 20.0 * pow3(1.5 - q);
      if (q < 0.5) r -= 40.0 * pow3(0.5 - q);
      return r;
    }
    case KernelType::M6: {
      double r = -5.0 * pow4(3.0 - q);
      if (q < 2.0) r += 30.0 * pow4(2.0 - q);
      if (q < 1.0) r -= 75.0 * pow4(1.0 - q);
      return r;
    }
    case KernelType::Gaussian:
      return -2.0 * q * std::exp(-q * q);
    case KernelType::WendlandC2: {
      // d/dq = 0.5 d/ds; 1D: d/ds[(1-s)^3(1+3s)] = -12 s (1-s)^2; 2D/3D: d/ds[(1-s)^4(1+4s)] = -20 s (1-s)^3
      const double s = 0.5 * q;
      return 0.5 * (dim_ == 1 ? -12.0 * s * (1.0 - s) * (1.0 - s) : -20.0 * s * pow3(1.0 - s));
    }
    case KernelType::WendlandC4: {
      // 1D: d/ds[(1-s)^5(1+5s+8s^2)] = -14 s (1+4s) (1-s)^4
      // 2D/3D: d/ds[(1-s)^6(1+6s+35/3 s^2)] = -56/3 s (1+5s) (1-s)^5
      const double s = 0.5 * q;
      return 0.5 * (dim_ == 1 ? -14.0 * s * (1.0 + 4.0 * s) * pow4(1.0 - s)
                              : -56.0 / 3.0 * s * (1.0 + 5.0 * s) * pow5(1.0 - s));
    }
  }
  return 0.0;
}

double Kernel::W(double r, double h) const {
  const double hinv = 1.0 / h;
  double hd = hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return sigma_ * hd * w(r * hinv);
}

double Kernel::dWdr(double r, double h) const {
  const double hinv = 1.0 / h;
  double hd = hinv * hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return sigma_ * hd * dw(r * hinv);
}

double Kernel::dWdh(double r, double h) const {
  // W = sigma w(r/h)/h^d  =>  dW/dh = -(d W + q sigma w'(q)/h^d)/h  (seed 000 eq. 3.3.2 needs it)
  const double hinv = 1.0 / h;
  const double q = r * hinv;
  double hd = hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return -sigma_ * hd * hinv * (dim_ * w(q) + q * dw(q));
}

double Kernel::default_eta() const {
  // Variance of the 1D profile w(q) in units of h^2, by Simpson's rule on [0, support].
  const int n = 2000;
  const double dq = support_ / n;
  double m0 = 0.0, m2 = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double q = k * dq;
    const double c = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    m0 += c * w(q);
    m2 += c * q * q * w(q);
  }
  const double variance = m2 / m0;
  const double m4_variance = 1.0 / 3.0;  // M4 = cardinal cubic B-spline, variance 4/12
  return 1.2 * std::sqrt(m4_variance / variance);
}

double expected_neighbours(const Kernel& k, double eta) {
  const double R = k.support() * eta;
  switch (k.dim()) {
    case 1: return 2.0 * R;
    case 2: return pi * R * R;
    default: return 4.0 / 3.0 * pi * R * R * R;
  }
}

}  // namespace sph
