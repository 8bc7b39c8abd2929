// The corrected kernel gradient of seed 001 (the mixed kernel-gradient correction of Bonet & Lok 1999,
// eqs. 33-36), per pair, from the per-particle factors the gradient-correction stage stores:
//   K0*_a(b) = W_ab / S_a,  S_a = sum_c V_c W_ac                                   (eq. 33, order-0 kernel)
//   grad K0*_a(b) = grad_a W_ab / S_a - W_ab grad S_a / S_a^2                      (eq. 34)
//   G_a(b) = L_a grad K0*_a(b),  L_a = [sum_b V_b grad K0*_a(b) (x_b - x_a)^T]^-1   (eqs. 35-36)
// so that sum_b V_b f_b G_a(b) is exact for linear f (and 0 for constant f). grad_a = d/dx_a.
#pragma once
#include <array>

#include "sph/kernel.h"
#include "sph/particles.h"

namespace sph {

/// Read-only views of the correction fields (3 x 3 storage; unused components 0).
struct CorrectionFields {
  const std::vector<double>* S = nullptr;
  std::array<const std::vector<double>*, 3> dS{};
  std::array<const std::vector<double>*, 9> L{};
  int dim = 2;

  explicit CorrectionFields(const Particles& p) : dim(p.dim()) {
    S = &p[Field::Shepard];
    for (int k = 0; k < dim; ++k) dS[k] = &p[component(Field::ShepardGradX, k)];
    for (int k = 0; k < dim; ++k)
      for (int l = 0; l < dim; ++l) L[3 * k + l] = &p[component(Field::CorrXX, k, l)];
  }

  /// G_a(b): the corrected gradient at a of the kernel of b. r = x_a - x_b, W = W(r, h_a),
  /// dWdr = dW/dr(r, h_a); r_inv = 1/|r| (0 for b = a).
  void gradient(std::size_t a, const double r[3], double W, double dWdr, double r_inv, double out[3]) const {
    const double s = (*S)[a], sinv = 1.0 / s;
    double g0[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < dim; ++k) g0[k] = (r[k] * r_inv * dWdr - W * (*dS[k])[a] * sinv) * sinv;
    for (int k = 0; k < 3; ++k) out[k] = 0.0;
    for (int k = 0; k < dim; ++k) {
      double acc = 0.0;
      for (int l = 0; l < dim; ++l) acc += (*L[3 * k + l])[a] * g0[l];
      out[k] = acc;
    }
  }
};

}  // namespace sph
