// The kernel-gradient correction stage (seed 001 eqs. 33-36, Bonet & Lok 1999): per particle, the
// Shepard sum S, its gradient, and the d x d matrix L that makes the corrected gradient exact for linear
// fields, solved with small Eigen matrices. Guard: near a free surface or with few neighbours the
// moment matrix M = sum_b V_b grad K0*_a(b) (x_b - x_a)^T becomes ill-conditioned; when its reciprocal
// condition number d / (|M|_F |M^-1|_F) (1 for a multiple of the identity, ~2 s_min/s_max when poorly
// conditioned) falls below correction.min_rcond, or M is singular, L = I is used instead (the order-0
// corrected kernel, still exact for constants) and the particle is counted and marked in 'fallback'.
#include <Eigen/Dense>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

template <int D>
std::size_t correct(StageContext& c) {
  using Mat = Eigen::Matrix<double, D, D>;
  using Vec = Eigen::Matrix<double, D, 1>;
  const Kernel& K = c.kernel;
  Particles& p = c.p;
  const bool walls_in = c.walls_in_sums();
  const std::size_t n = walls_in ? p.size() : p.fluid();  // dummy walls need their own correction
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  auto& S = p[Field::Shepard];
  auto& fallback = p[Field::CorrFallback];
  std::vector<double>* dS[D];
  std::vector<double>* L[D][D];
  for (int k = 0; k < D; ++k) {
    dS[k] = &p[component(Field::ShepardGradX, k)];
    for (int l = 0; l < D; ++l) L[k][l] = &p[component(Field::CorrXX, k, l)];
  }
  const double support = K.support();
  const double min_rcond = c.prm.correction.min_rcond;
  std::size_t fallbacks = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : fallbacks) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double hi = h[i], R2 = support * support * hi * hi;
    // pass 1: S and grad S
    double s = 0.0;
    Vec ds = Vec::Zero();
    for (std::uint32_t j : c.nl.of(i)) {
      if (!walls_in && p.kind[j]) continue;
      Vec r;
      for (int k = 0; k < D; ++k) r[k] = p.x[k][i] - p.x[k][j];
      const double r2 = r.squaredNorm();
      if (r2 >= R2) continue;
      const double rr = std::sqrt(r2), V = m[j] / rho[j];
      s += V * K.W(rr, hi);
      if (rr > 0.0) ds += V * K.dWdr(rr, hi) / rr * r;
    }
    // pass 2: M = sum V grad K0* (x_j - x_i)^T
    Mat M = Mat::Zero();
    for (std::uint32_t j : c.nl.of(i)) {
      if (!walls_in && p.kind[j]) continue;
      Vec r;
      for (int k = 0; k < D; ++k) r[k] = p.x[k][i] - p.x[k][j];
      const double r2 = r.squaredNorm();
      if (r2 >= R2 || r2 == 0.0) continue;
      const double rr = std::sqrt(r2), V = m[j] / rho[j];
      const Vec g0 = (K.dWdr(rr, hi) / rr * r - K.W(rr, hi) * ds / s) / s;
      M -= V * g0 * r.transpose();  // (x_j - x_i) = -r
    }
    Mat Li = Mat::Identity();
    bool fell_back = true;
    const double det = M.determinant();
    if (std::isfinite(det) && det != 0.0) {
      const Mat inv = M.inverse();
      const double rcond = D / (M.norm() * inv.norm());
      if (std::isfinite(rcond) && rcond >= min_rcond) {
        Li = inv;
        fell_back = false;
      }
    }
    if (fell_back) ++fallbacks;
    S[i] = s;
    fallback[i] = fell_back ? 1.0 : 0.0;
    for (int k = 0; k < D; ++k) {
      (*dS[k])[i] = ds[k];
      for (int l = 0; l < D; ++l) (*L[k][l])[i] = Li(k, l);
    }
  }
  return fallbacks;
}

class GradientCorrection final : public Stage {
 public:
  explicit GradientCorrection(int dim) : dim_(dim) {}
  std::string_view name() const override { return "kernel-gradient correction"; }
  FieldSet needs() const override { return FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::H); }
  FieldSet writes() const override { return shares().add(Field::CorrFallback); }
  FieldSet shares() const override {
    FieldSet f;
    f.add(Field::Shepard);
    for (int k = 0; k < dim_; ++k) {
      f.add(component(Field::ShepardGradX, k));
      for (int l = 0; l < dim_; ++l) f.add(component(Field::CorrXX, k, l));
    }
    return f;
  }
  bool run(StageContext& c) override {
    switch (dim_) {
      case 1: c.stats.correction_fallbacks = correct<1>(c); break;
      case 2: c.stats.correction_fallbacks = correct<2>(c); break;
      default: c.stats.correction_fallbacks = correct<3>(c); break;
    }
    return true;
  }

 private:
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_gradient_correction(int dim) { return std::make_unique<GradientCorrection>(dim); }

}  // namespace sph
