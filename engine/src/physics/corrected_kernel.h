// The corrected kernel gradient of seed 001 (the mixed kernel-gradient correction of Bonet & Lok 1999,
// eqs. 33-36), per pair, from the per-particle factors the gradient-correction stage stores:
//   K0*_a(b) = W_ab / S_a,  S_a = sum_c V_c W_ac                                   (eq. 33, order-0 kernel)
//   grad K0*_a(b) = grad_a W_ab / S_a - W_ab grad S_a / S_a^2                      (eq. 34)
//   G_a(b) = L_a grad K0*_a(b),  L_a = [sum_b V_b grad K0*_a(b) (x_b - x_a)^T]^-1   (eqs. 35-36)
// so that sum_b V_b f_b G_a(b) is exact for linear f (and 0 for constant f). grad_a = d/dx_a. Stored
// as A_a = L_a / S_a and c_a = L_a grad S_a / S_a^2, so that G_a(b) = A_a grad_a W_ab - W_ab c_a costs
// a d x d product and no division per pair.
#pragma once
#include <array>

#include "sph/kernel.h"
#include "sph/particles.h"

namespace sph {

/// Read-only views of the correction fields (unused components absent).
struct CorrectionFields {
  std::array<const double*, 3> c{};
  std::array<const double*, 9> A{};
  int dim = 2;

  explicit CorrectionFields(const Particles& p) : dim(p.dim()) {
    for (int k = 0; k < dim; ++k) c[k] = p[component(Field::CorrCX, k)].data();
    for (int k = 0; k < dim; ++k)
      for (int l = 0; l < dim; ++l) A[3 * k + l] = p[component(Field::CorrXX, k, l)].data();
  }

  /// G_a(b): the corrected gradient at a of the kernel of b, for r = x_a - x_b, W = W(r, h_a),
  /// dWdr_r = dW/dr(r, h_a) / |r| (0 for b = a). Components 0..D-1 of out.
  template <int D>
  void gradient_d(std::size_t a, const double* r, double W, double dWdr_r, double* out) const {
    for (int k = 0; k < D; ++k) {
      double acc = -W * c[k][a];
      for (int l = 0; l < D; ++l) acc += A[3 * k + l][a] * r[l] * dWdr_r;
      out[k] = acc;
    }
  }
  /// The same for a dimension known at run time (components beyond it are 0).
  void gradient(std::size_t a, const double r[3], double W, double dWdr_r, double out[3]) const {
    out[0] = out[1] = out[2] = 0.0;
    switch (dim) {
      case 1: gradient_d<1>(a, r, W, dWdr_r, out); break;
      case 2: gradient_d<2>(a, r, W, dWdr_r, out); break;
      default: gradient_d<3>(a, r, W, dWdr_r, out); break;
    }
  }
};

}  // namespace sph
