// Smoothing kernels W(r, h) = sigma_d w(q) / h^d, q = r/h (seed 000 eqs. 3.2.6–3.2.11).
// A Kernel is a small value chosen at runtime; evaluation is branch-light and inlined per family.
#pragma once
#include "sph/params.h"

namespace sph {

class Kernel {
 public:
  Kernel(KernelType type, int dim);

  KernelType type() const { return type_; }
  int dim() const { return dim_; }
  /// Support radius in units of h: W = 0 for q >= support().
  double support() const { return support_; }
  /// Normalisation sigma_d so that the integral of W over R^d is 1.
  double sigma() const { return sigma_; }
  /// The default eta of h = eta (m/rho)^(1/d) for this kernel: chosen so that every kernel has the
  /// same standard deviation in units of the particle spacing as M4 with eta = 1.2 (Price 2012,
  /// JCP 231, 759, sec. 2.1.6; the B-spline M_n with unit knot spacing has variance n/12).
  double default_eta() const { return default_eta_; }

  /// Dimensionless shape w(q) (without sigma).
  double w(double q) const;
  /// dw/dq (without sigma).
  double dw(double q) const;

  /// W(r, h) [1/length^d].
  double W(double r, double h) const;
  /// dW/dr (r, h) [1/length^(d+1)]; the gradient is (r_vec/r) dW/dr.
  double dWdr(double r, double h) const;
  /// dW/dh (r, h) = -(d W + r dW/dr)/h (used by the Omega term, seed 000 eq. 3.3.2).
  double dWdh(double r, double h) const;

  /// Per-particle factors of W and dW/dr for one h, computed once per particle in the pair loops:
  /// W = w_norm w(q), dW/dr = dw_norm dw/dq(q), q = r hinv.
  struct Scale {
    double hinv = 0.0, w_norm = 0.0, dw_norm = 0.0;
  };
  Scale scale(double h) const;
  /// w(q) and dw/dq(q) together (one pass over the shared polynomial terms; branch-free for M4).
  void w_dw(double q, double& w, double& dw) const;
  /// W(r, h) and dW/dr(r, h) from the factors of h.
  void eval(const Scale& s, double r, double& W, double& dWdr) const;

 private:
  KernelType type_;
  int dim_;
  double support_ = 2.0;
  double sigma_ = 1.0;
  double default_eta_ = 1.2;
  double compute_default_eta() const;
};

/// Expected neighbour count within the support for a uniform lattice: V_d (support eta)^d.
double expected_neighbours(const Kernel& k, double eta);

}  // namespace sph

#include "sph/kernel_eval.h"
