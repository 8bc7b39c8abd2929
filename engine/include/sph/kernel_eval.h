// Inline evaluation of the kernel shapes (hot loops): seed 000 eqs. 3.2.6–3.2.11, Wendland C2/C4.
// Included by kernel.h; not a public header on its own.
#pragma once
#include <cmath>

#include "sph/kernel_shapes.h"

namespace sph {

inline double Kernel::w(double q) const {
  return shape::with_shape(type_, dim_, [q](auto s) __attribute__((always_inline)) { return s.w(q); });
}

inline double Kernel::dw(double q) const {
  return shape::with_shape(type_, dim_, [q](auto s) __attribute__((always_inline)) { return s.dw(q); });
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
  if (type_ == KernelType::M4) {  // the liquids' kernel: a single compare instead of the dispatch
    const shape::M4 s;
    w_out = s.w(q);
    dw_out = s.dw(q);
    return;
  }
  // one dispatch for both: inside it the shape's clamped terms are shared by w and dw
  shape::with_shape(type_, dim_, [&](auto s) __attribute__((always_inline)) {
    w_out = s.w(q);
    dw_out = s.dw(q);
  });
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
