// Inline evaluation of the kernel shapes (hot loops): seed 000 eqs. 3.2.6–3.2.11, Wendland C2/C4.
// Included by kernel.h; not a public header on its own.
#pragma once
#include <cmath>

namespace sph {

namespace kernel_detail {
inline double pow3(double x) { return x * x * x; }
inline double pow4(double x) { return (x * x) * (x * x); }
inline double pow5(double x) { return pow4(x) * x; }
inline double pow6(double x) { return pow3(x) * pow3(x); }
}  // namespace kernel_detail

inline double Kernel::w(double q) const {
  if (q >= support_) return 0.0;
  switch (type_) {
    case KernelType::M4:  // seed 000 eq. 3.2.7
      return q < 1.0 ? 0.25 * kernel_detail::pow3(2.0 - q) - kernel_detail::pow3(1.0 - q) : 0.25 * kernel_detail::pow3(2.0 - q);
    case KernelType::M5: {  // seed 000 eq. 3.2.8
      double r = kernel_detail::pow4(2.5 - q);
      if (q < 1.5) r -= 5.0 * kernel_detail::pow4(1.5 - q);
      if (q < 0.5) r += 10.0 * kernel_detail::pow4(0.5 - q);
      return r;
    }
    case KernelType::M6: {  // seed 000 eq. 3.2.9
      double r = kernel_detail::pow5(3.0 - q);
      if (q < 2.0) r -= 6.0 * kernel_detail::pow5(2.0 - q);
      if (q < 1.0) r += 15.0 * kernel_detail::pow5(1.0 - q);
      return r;
    }
    case KernelType::Gaussian:  // seed 000 eq. 3.2.6
      return std::exp(-q * q);
    case KernelType::WendlandC2: {
      const double s = 0.5 * q;
      return dim_ == 1 ? kernel_detail::pow3(1.0 - s) * (1.0 + 3.0 * s) : kernel_detail::pow4(1.0 - s) * (1.0 + 4.0 * s);
    }
    case KernelType::WendlandC4: {
      const double s = 0.5 * q;
      return dim_ == 1 ? kernel_detail::pow5(1.0 - s) * (1.0 + 5.0 * s + 8.0 * s * s)
                       : kernel_detail::pow6(1.0 - s) * (1.0 + 6.0 * s + 35.0 / 3.0 * s * s);
    }
  }
  return 0.0;
}

inline double Kernel::dw(double q) const {
  if (q >= support_) return 0.0;
  switch (type_) {
    case KernelType::M4:
      return q < 1.0 ? -0.75 * (2.0 - q) * (2.0 - q) + 3.0 * (1.0 - q) * (1.0 - q)
                     : -0.75 * (2.0 - q) * (2.0 - q);
    case KernelType::M5: {
      double r = -4.0 * kernel_detail::pow3(2.5 - q);
      if (q < 1.5) r += 20.0 * kernel_detail::pow3(1.5 - q);
      if (q < 0.5) r -= 40.0 * kernel_detail::pow3(0.5 - q);
      return r;
    }
    case KernelType::M6: {
      double r = -5.0 * kernel_detail::pow4(3.0 - q);
      if (q < 2.0) r += 30.0 * kernel_detail::pow4(2.0 - q);
      if (q < 1.0) r -= 75.0 * kernel_detail::pow4(1.0 - q);
      return r;
    }
    case KernelType::Gaussian:
      return -2.0 * q * std::exp(-q * q);
    case KernelType::WendlandC2: {
      // d/dq = 0.5 d/ds; 1D: d/ds[(1-s)^3(1+3s)] = -12 s (1-s)^2; 2D/3D: d/ds[(1-s)^4(1+4s)] = -20 s (1-s)^3
      const double s = 0.5 * q;
      return 0.5 * (dim_ == 1 ? -12.0 * s * (1.0 - s) * (1.0 - s) : -20.0 * s * kernel_detail::pow3(1.0 - s));
    }
    case KernelType::WendlandC4: {
      // 1D: d/ds[(1-s)^5(1+5s+8s^2)] = -14 s (1+4s) (1-s)^4
      // 2D/3D: d/ds[(1-s)^6(1+6s+35/3 s^2)] = -56/3 s (1+5s) (1-s)^5
      const double s = 0.5 * q;
      return 0.5 * (dim_ == 1 ? -14.0 * s * (1.0 + 4.0 * s) * kernel_detail::pow4(1.0 - s)
                              : -56.0 / 3.0 * s * (1.0 + 5.0 * s) * kernel_detail::pow5(1.0 - s));
    }
  }
  return 0.0;
}

inline Kernel::Scale Kernel::scale(double h) const {
  Scale s;
  s.hinv = 1.0 / h;
  double hd = s.hinv;
  for (int k = 1; k < dim_; ++k) hd *= s.hinv;
  s.w_norm = sigma_ * hd;
  s.dw_norm = sigma_ * hd * s.hinv;
  return s;
}

[[gnu::always_inline]] inline void Kernel::w_dw(double q, double& w_out, double& dw_out) const {
  if (type_ == KernelType::M4) {  // seed 000 eq. 3.2.7, as clamped powers: no branch on q
    const double t = q < 2.0 ? 2.0 - q : 0.0, u = q < 1.0 ? 1.0 - q : 0.0;
    w_out = 0.25 * t * t * t - u * u * u;
    dw_out = -0.75 * t * t + 3.0 * u * u;
    return;
  }
  w_out = w(q);
  dw_out = dw(q);
}

[[gnu::always_inline]] inline void Kernel::eval(const Scale& s, double r, double& W_out, double& dWdr_out) const {
  double w0, dw0;
  w_dw(r * s.hinv, w0, dw0);
  W_out = s.w_norm * w0;
  dWdr_out = s.dw_norm * dw0;
}

inline double Kernel::W(double r, double h) const {
  const double hinv = 1.0 / h;
  double hd = hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return sigma_ * hd * w(r * hinv);
}

inline double Kernel::dWdr(double r, double h) const {
  const double hinv = 1.0 / h;
  double hd = hinv * hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return sigma_ * hd * dw(r * hinv);
}

inline double Kernel::dWdh(double r, double h) const {
  // W = sigma w(r/h)/h^d  =>  dW/dh = -(d W + q sigma w'(q)/h^d)/h  (seed 000 eq. 3.3.2 needs it)
  const double hinv = 1.0 / h;
  const double q = r * hinv;
  double hd = hinv;
  for (int k = 1; k < dim_; ++k) hd *= hinv;
  return -sigma_ * hd * hinv * (dim_ * w(q) + q * dw(q));
}

}  // namespace sph
