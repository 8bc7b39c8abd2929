// Tabulation of the kernel-softened law: M(q) = int_0^q 4 pi s^2 W(s, 1) ds on a fine grid (trapezoid
// on 8 sub-steps per table interval), normalised so that M(support) = 1 (the truncated
// Gaussian holds slightly less than 1), then Psi(q) = 1/S + int_q^S M(s)/s^2 ds, so that phi is
// continuous with -1/r at the support S.
#include "gravity/softening.h"

#include <numbers>

#include "sph/kernel.h"

namespace sph::gravity {
namespace {
constexpr std::size_t kIntervals = 4096, kFine = 8;
}

KernelSoftening::KernelSoftening(KernelType type) {
  const Kernel K(type, 3);
  support_ = K.support();
  const std::size_t nf = kIntervals * kFine;
  const double dqf = support_ / static_cast<double>(nf);
  std::vector<double> M(nf + 1, 0.0);
  auto dm = [&](double q) { return 4.0 * std::numbers::pi * q * q * K.W(q, 1.0); };
  for (std::size_t k = 1; k <= nf; ++k) {
    const double a = dqf * static_cast<double>(k - 1), b = dqf * static_cast<double>(k);
    M[k] = M[k - 1] + dqf / 6.0 * (dm(a) + 4.0 * dm(0.5 * (a + b)) + dm(b));  // Simpson on each fine step
  }
  const double total = M[nf];
  for (double& m : M) m /= total;
  std::vector<double> Psi(nf + 1, 0.0);
  Psi[nf] = 1.0 / support_;
  auto g = [&](std::size_t k) { return M[k] / ((dqf * k) * (dqf * k)); };
  for (std::size_t k = nf; k-- > 1;) Psi[k] = Psi[k + 1] + 0.5 * dqf * (g(k) + g(k + 1));
  // the first fine step: M ~ c q^3, so M/q^2 ~ c q integrates to about half its value at dqf
  Psi[0] = Psi[1] + 0.5 * dqf * g(1);
  inv_dq_ = static_cast<double>(kIntervals) / support_;
  dq_ = support_ / static_cast<double>(kIntervals);
  dPsi_.resize(kIntervals + 1);
  F_.resize(kIntervals + 1);
  Psi_.resize(kIntervals + 1);
  M_.resize(kIntervals + 1);
  Z_.resize(kIntervals + 1);
  const double w0 = (4.0 / 3.0) * std::numbers::pi * K.W(0.0, 1.0) / total;  // lim M/q^3 at q = 0
  for (std::size_t k = 0; k <= kIntervals; ++k) {
    const std::size_t kf = k * kFine;
    const double q = dqf * static_cast<double>(kf);
    M_[k] = M[kf];
    F_[k] = k == 0 ? w0 : M[kf] / (q * q * q);
    Psi_[k] = Psi[kf];
    dPsi_[k] = k == 0 ? 0.0 : -M[kf] / (q * q);
    Z_[k] = k == 0 ? Psi[0] : k == kIntervals ? 0.0 : Psi[kf] - M[kf] / q;
  }
}

double KernelSoftening::enclosed(double q) const {
  if (q >= support_) return 1.0;
  const double t = q * inv_dq_;
  const std::size_t k = static_cast<std::size_t>(t);
  return M_[k] + (t - static_cast<double>(k)) * (M_[k + 1] - M_[k]);
}

}  // namespace sph::gravity
