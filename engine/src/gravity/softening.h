// Short-range laws of self-gravity. A pair law gives, for a squared separation r2 and the two
// smoothing lengths, f and phi with a_i = -G m_j f (x_i - x_j) and phi_i = G m_j phi:
//  - Plummer: f = (r^2 + eps^2)^(-3/2), phi = -(r^2 + eps^2)^(-1/2) (seed 003 eq. 2.43, whose printed
//    denominator (|x| + eps^2)^3 is a misprint for (|x|^2 + eps^2)^(3/2));
//  - kernel: each mass spread like the SPH kernel of its h (Price & Monaghan 2007, MNRAS 374, 1347),
//    f = M(r/h)/r^3 with M the kernel mass inside r, exactly Newtonian beyond the support; symmetrised
//    as the mean of the laws of h_i and h_j, so the pair force is antisymmetric. Its grad-h term (their
//    zeta term, which needs dphi/dh below) is the stage physics/gravity_grad_h.cpp.
#pragma once
#include <cmath>
#include <vector>

#include "sph/params.h"

namespace sph::gravity {

/// The kernel-softened law of one kernel family (always the 3D kernel: gravity is the 3D 1/r^2 law in
/// every dimension), tabulated in q = r/h on 4096 intervals of the support.
class KernelSoftening {
 public:
  explicit KernelSoftening(KernelType type);
  double support() const { return support_; }
  /// f [1/length^3] and phi [1/length] of one particle of smoothing length h at distance r.
  void eval(double r, double h, double& f, double& phi) const {
    const double q = r / h;
    if (q >= support_) {
      const double inv = 1.0 / r;
      f = inv * inv * inv;
      phi = -inv;
      return;
    }
    const double t = q * inv_dq_;
    const std::size_t k = static_cast<std::size_t>(t);
    const double s = t - static_cast<double>(k);
    const double hinv = 1.0 / h;
    f = (F_[k] + s * (F_[k + 1] - F_[k])) * hinv * hinv * hinv;
    // cubic Hermite in Psi with its exact slopes dPsi/dq = -M/q^2: -dphi/dr matches f r to O(dq^2)
    const double s2 = s * s, s3 = s2 * s;
    const double psi = (2 * s3 - 3 * s2 + 1) * Psi_[k] + (s3 - 2 * s2 + s) * dq_ * dPsi_[k] +
                       (-2 * s3 + 3 * s2) * Psi_[k + 1] + (s3 - s2) * dq_ * dPsi_[k + 1];
    phi = -psi * hinv;
  }
  /// dphi/dh [1/length^2] of one particle of smoothing length h at distance r: with phi = -Psi(q)/h,
  /// dphi/dh = (Psi(q) - M(q)/q) / h^2, zero beyond the support (Price & Monaghan 2007, eq. 27).
  double dphi_dh(double r, double h) const {
    const double q = r / h;
    if (q >= support_) return 0.0;
    const double t = q * inv_dq_;
    const std::size_t k = static_cast<std::size_t>(t);
    const double s = t - static_cast<double>(k);
    const double hinv = 1.0 / h;
    return (Z_[k] + s * (Z_[k + 1] - Z_[k])) * hinv * hinv;
  }
  /// The enclosed kernel mass fraction M(q) (for tests).
  double enclosed(double q) const;

 private:
  double support_ = 2.0, inv_dq_ = 0.0, dq_ = 0.0;
  std::vector<double> F_;    ///< M(q)/q^3
  std::vector<double> Psi_;  ///< -phi h: 1/q beyond the support
  std::vector<double> dPsi_;  ///< dPsi/dq = -M/q^2
  std::vector<double> M_;    ///< M(q)
  std::vector<double> Z_;    ///< Psi(q) - M(q)/q = h^2 dphi/dh: 0 at the support
};

/// The pair law of a run (see the file comment).
struct PairLaw {
  Softening kind = Softening::Plummer;
  double eps2 = 0.0;                    ///< Plummer eps^2 [length^2]
  const KernelSoftening* kernel = nullptr;

  void operator()(double r2, double hi, double hj, double& f, double& phi) const {
    if (kind == Softening::Plummer) {
      const double inv = 1.0 / std::sqrt(r2 + eps2);
      f = inv * inv * inv;
      phi = -inv;
      return;
    }
    const double r = std::sqrt(r2);
    double fi, pi, fj, pj;
    kernel->eval(r, hi, fi, pi);
    kernel->eval(r, hj, fj, pj);
    f = 0.5 * (fi + fj);
    phi = 0.5 * (pi + pj);
  }
  /// Squared length below which the law departs from Newton's (for the pair dynamical time).
  double soft2(double hi, double hj) const {
    if (kind == Softening::Plummer) return eps2;
    const double s = kernel->support() * 0.5 * (hi + hj);
    return s * s;
  }
};

}  // namespace sph::gravity
