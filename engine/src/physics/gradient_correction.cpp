// The kernel-gradient correction stage (seed 001 eqs. 33-36, Bonet & Lok 1999): per particle, the
// Shepard sum S, its gradient, and the d x d matrix L that makes the corrected gradient exact for linear
// fields, solved with small Eigen matrices; stored as A = L/S and c = L grad S / S^2 (corrected_kernel.h). Guard: near a free surface or with few neighbours the
// moment matrix M = sum_b V_b grad K0*_a(b) (x_b - x_a)^T becomes ill-conditioned; when its reciprocal
// condition number d / (|M|_F |M^-1|_F) (1 for a multiple of the identity, ~2 s_min/s_max when poorly
// conditioned) falls below correction.min_rcond, or M is singular, L = I is used instead (the order-0
// corrected kernel, still exact for constants) and the particle is counted and marked in 'fallback'.
#include <Eigen/Dense>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "pair_block.h"
#include "pair_fields.h"
#include "sph/kernel_shapes.h"

namespace sph {
namespace {

/// Columns of the pair terms: S, grad S (D), T2 (D), T1 (D x D, row by row).
constexpr int columns(int D) { return 1 + 2 * D + D * D; }

/// The sums of particle i's pairs within R2 = (support h_i)^2, in list order (pair_block.h): with
/// r = x_i - x_j, S = sum V W, grad S = sum V (dW/(r dr)) r, T2 = sum V W r and T1 = sum V (dW/(r dr))
/// r r^T, at sum[0], sum[1..D], sum[1+D..2D] and sum[1+2D..] (row by row). The terms per pair are
/// vectorised. V: m / rho of every particle.
template <int D, class Shape>
void moment_sums(const StageContext& c, const Shape& shape, const double* V, std::size_t i, bool skip_walls,
                 PairBlock<columns(D)>& b, double sum[columns(D)]) {
  constexpr int kCols = columns(D);
  const double hi = c.p[Field::H][i], R2 = c.kernel.support() * c.kernel.support() * hi * hi;
  const Kernel::Scale si = c.kernel.scale(hi);
  const std::size_t np = gather_within(c.p, i, c.nl.of(i), R2, skip_walls, b);
  const std::uint32_t* J = b.j.data();
  const double* RX[3] = {b.dx.data(), b.dy.data(), b.dz.data()};
  const double* RR = b.r2.data();
  double* col[kCols];
  for (int q = 0; q < kCols; ++q) col[q] = b[q];
#pragma omp simd
  for (std::size_t k = 0; k < np; ++k) {
    const double rr = std::sqrt(RR[k]);
    const double qi = rr * si.hinv;
    const double W = si.w_norm * shape.w(qi), dWdr = si.dw_norm * shape.dw(qi);
    const double Vj = V[J[k]];
    const double VW = Vj * W, VdW = rr > 0.0 ? Vj * dWdr / rr : 0.0;
    col[0][k] = VW;
    for (int q = 0; q < D; ++q) {
      const double r = RX[q][k];
      col[1 + q][k] = VdW * r;
      col[1 + D + q][k] = VW * r;
      for (int l = 0; l < D; ++l) col[1 + 2 * D + D * q + l][k] = VdW * r * RX[l][k];
    }
  }
  for (int q = 0; q < kCols; ++q) sum[q] = 0.0;
  for (std::size_t k = 0; k < np; ++k)
    for (int q = 0; q < kCols; ++q) sum[q] += col[q][k];
}

/// L = M^-1, or the identity when M is singular or its reciprocal condition number d / (|M|_F |M^-1|_F)
/// is below min_rcond; returns whether it fell back.
template <int D>
bool invert_guarded(const Eigen::Matrix<double, D, D>& M, double min_rcond, Eigen::Matrix<double, D, D>& L) {
  using Mat = Eigen::Matrix<double, D, D>;
  L = Mat::Identity();
  const double det = M.determinant();
  if (std::isfinite(det) && det != 0.0) {
    const Mat inv = M.inverse();
    const double rcond = D / (M.norm() * inv.norm());
    if (std::isfinite(rcond) && rcond >= min_rcond) {
      L = inv;
      return false;
    }
  }
  return true;
}

template <int D, class Shape>
std::size_t correct(StageContext& c, const Shape& shape, std::vector<double>& vol) {
  using Mat = Eigen::Matrix<double, D, D>;
  Particles& p = c.p;
  const bool walls_in = c.walls_in_sums();
  const std::size_t n = walls_in ? p.size() : p.fluid();  // dummy walls need their own correction
  const KernelFields f(p);
  double* S = p[Field::Shepard].data();
  double* fallback = p[Field::CorrFallback].data();
  double* C[D];
  double* A[D][D];
  for (int k = 0; k < D; ++k) {
    C[k] = p[component(Field::CorrCX, k)].data();
    for (int l = 0; l < D; ++l) A[k][l] = p[component(Field::CorrXX, k, l)].data();
  }
  const double min_rcond = c.prm.correction.min_rcond;
  std::size_t fallbacks = 0;
  vol.resize(p.total());  // V = m / rho of every particle, ghosts included: one division each
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t j = 0; j < vol.size(); ++j) vol[j] = f.m[j] / f.rho[j];
#pragma omp parallel reduction(+ : fallbacks) if (p.size() >= kParallelMin)
  {
  PairBlock<columns(D)> b;  // this thread's pairs of i
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
  for (std::size_t i = 0; i < n; ++i) {
    // grad K0* = (grad W - W grad S / S) / S, so M = sum V grad K0* (x_j - x_i)^T = -T1 / S + grad S T2^T / S^2
    double sum[columns(D)];
    moment_sums<D>(c, shape, vol.data(), i, !walls_in, b, sum);
    const double s = sum[0];
    const double* ds = sum + 1;
    const double* t2 = sum + 1 + D;
    const double* t1 = sum + 1 + 2 * D;
    const double sinv = 1.0 / s;
    Mat M;
    for (int k = 0; k < D; ++k)
      for (int l = 0; l < D; ++l) M(k, l) = (-t1[D * k + l] + ds[k] * t2[l] * sinv) * sinv;
    Mat Li;
    const bool fell_back = invert_guarded<D>(M, min_rcond, Li);
    if (fell_back) ++fallbacks;
    S[i] = s;
    fallback[i] = fell_back ? 1.0 : 0.0;
    for (int k = 0; k < D; ++k) {
      double ck = 0.0;
      for (int l = 0; l < D; ++l) {
        ck += Li(k, l) * ds[l];
        A[k][l][i] = Li(k, l) * sinv;
      }
      C[k][i] = ck * sinv * sinv;
    }
  }
  }
  return fallbacks;
}

template <int D>
std::size_t correct(StageContext& c, std::vector<double>& vol) {
  // the kernel shape is chosen once here, not per pair
  return shape::with_shape(c.kernel.type(), D, [&](auto s) { return correct<D>(c, s, vol); });
}

/// S, c and A up to the dimension: what the neighbours' corrected gradients read.
FieldSet correction_fields(int dim) {
  return FieldSet{Field::Shepard}.add_vector(Field::CorrCX, dim).add_tensor(Field::CorrXX, dim);
}

class GradientCorrection final : public Stage {
 public:
  explicit GradientCorrection(int dim)
      : Stage({.name = "kernel-gradient correction",
               .needs = {Field::Mass, Field::Density, Field::H},
               .writes = correction_fields(dim).add(Field::CorrFallback),
               .shares = correction_fields(dim)}),
        dim_(dim) {}
  bool run(StageContext& c) override {
    switch (dim_) {
      case 1: c.stats.correction_fallbacks = correct<1>(c, vol_); break;
      case 2: c.stats.correction_fallbacks = correct<2>(c, vol_); break;
      default: c.stats.correction_fallbacks = correct<3>(c, vol_); break;
    }
    return true;
  }

 private:
  int dim_;
  std::vector<double> vol_;  ///< per-particle m / rho, reused between evaluations
};

}  // namespace

std::unique_ptr<Stage> make_gradient_correction(int dim) { return std::make_unique<GradientCorrection>(dim); }

}  // namespace sph
