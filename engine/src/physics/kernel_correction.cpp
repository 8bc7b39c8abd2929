// MLS kernel correction of order 0 or 1 (see sph/kernel_correction.h; seed 001 eqs. 17-23).
#include "sph/kernel_correction.h"

#include <Eigen/Dense>
#include <cmath>

namespace sph {
namespace {

template <int D>
int weights_d(const Kernel& K, const Particles& p, std::size_t a, std::span<const std::uint32_t> nb, int order,
              double min_rcond, bool skip_walls, std::vector<double>& w) {
  using Vec = Eigen::Matrix<double, D + 1, 1>;
  using Mat = Eigen::Matrix<double, D + 1, D + 1>;
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const double h = p[Field::H][a], R2 = K.support() * K.support() * h * h;
  w.assign(nb.size(), 0.0);
  Mat A = Mat::Zero();
  double shepard = 0.0;
  for (std::size_t k = 0; k < nb.size(); ++k) {
    const std::uint32_t b = nb[k];
    if (skip_walls && p.kind[b]) continue;
    Vec q;
    q[0] = 1.0;
    double r2 = 0.0;
    for (int l = 0; l < D; ++l) {
      q[l + 1] = (p.x[l][b] - p.x[l][a]) / h;
      r2 += q[l + 1] * q[l + 1];
    }
    if (r2 * h * h >= R2) continue;
    const double VW = m[b] / rho[b] * K.W(std::sqrt(r2) * h, h);
    w[k] = VW;
    shepard += VW;
    if (order >= 1) A += VW * q * q.transpose();
  }
  if (order >= 1) {
    // beta = A^-1 p(0); K*_1 = beta . p(r_b) W  (eq. 22)
    const double det = A.determinant();
    bool ok = std::isfinite(det) && det != 0.0;
    Vec beta = Vec::Zero();
    if (ok) {
      const Mat inv = A.inverse();  // closed form for these sizes (2x2 to 4x4)
      const double rcond = (D + 1) / (A.norm() * inv.norm());
      ok = std::isfinite(rcond) && rcond >= min_rcond;
      beta = inv.col(0);
    }
    if (ok) {
      for (std::size_t k = 0; k < nb.size(); ++k) {
        if (w[k] == 0.0) continue;
        const std::uint32_t b = nb[k];
        double dot = beta[0];
        for (int l = 0; l < D; ++l) dot += beta[l + 1] * (p.x[l][b] - p.x[l][a]) / h;
        w[k] *= dot;
      }
      return 1;
    }
  }
  if (shepard > 0.0)  // order 0 (Shepard): K*_0 = W / sum V W (eq. 33)
    for (double& x : w) x /= shepard;
  return 0;
}

}  // namespace

int corrected_kernel_weights(const Kernel& K, const Particles& p, std::size_t a, std::span<const std::uint32_t> nb,
                             int order, double min_rcond, bool skip_walls, std::vector<double>& weights) {
  switch (p.dim()) {
    case 1: return weights_d<1>(K, p, a, nb, order, min_rcond, skip_walls, weights);
    case 2: return weights_d<2>(K, p, a, nb, order, min_rcond, skip_walls, weights);
    default: return weights_d<3>(K, p, a, nb, order, min_rcond, skip_walls, weights);
  }
}

}  // namespace sph
