// Kernel shapes and normalisations (seed 000 eqs. 3.2.6–3.2.11; Wendland 1995; Dehnen & Aly 2012, MNRAS 425, 1068).
#include "sph/kernel.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph {
namespace {

constexpr double pi = std::numbers::pi;


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
  default_eta_ = compute_default_eta();
}






double Kernel::compute_default_eta() const {
  // Variance of the 1D profile w(q) in units of h^2, by Simpson's rule on [0, support].
  const int n = 2000;
  const double dq = support_ / n;
  double m0 = 0.0, m2 = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double q = k < n ? k * dq : support_ * (1.0 - 1e-15);  // inside the support: w may jump at q = support
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
