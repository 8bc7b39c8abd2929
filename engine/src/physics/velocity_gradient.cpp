// The velocity gradient from corrected kernel gradients (seed 001 eq. 52): (dv_k/dx_l)_a =
// sum_b V_b (v_b - v_a)_k G_a(b)_l, exact for linear velocity fields. The corrected formulation's
// viscous stress 2 mu (D - tr D / 3 I) is built from it (seed 001 eq. 51).
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "corrected_kernel.h"

namespace sph {
namespace {

class VelocityGradient final : public Stage {
 public:
  explicit VelocityGradient(int dim)
      : Stage({.name = "velocity gradient (corrected)",
               .needs = {Field::Mass, Field::Density, Field::H},
               .writes = FieldSet{}.add_tensor(Field::VelGradXX, dim),
               .shares = FieldSet{}.add_tensor(Field::VelGradXX, dim)}),
        dim_(dim) {}
  bool run(StageContext& c) override {
    const Kernel& K = c.kernel;
    Particles& p = c.p;
    const bool walls_in = c.walls_in_sums();
    const std::size_t n = walls_in ? p.size() : p.fluid();
    const auto& m = p[Field::Mass];
    const auto& rho = p[Field::Density];
    const auto& h = p[Field::H];
    const CorrectionFields corr(p);
    const int d = dim_;
    std::vector<double>* out[9] = {};
    for (int k = 0; k < d; ++k)
      for (int l = 0; l < d; ++l) out[3 * k + l] = &p[component(Field::VelGradXX, k, l)];
    const double support = K.support();
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const double hi = h[i], R2 = support * support * hi * hi;
      const Kernel::Scale si = K.scale(hi);
      double g[9] = {};
      for (std::uint32_t j : c.nl.of(i)) {
        if (j == i || (!walls_in && p.kind[j])) continue;
        double r[3];
        for (int k = 0; k < 3; ++k) r[k] = p.x[k][i] - p.x[k][j];
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (r2 >= R2 || r2 == 0.0) continue;
        const double rr = std::sqrt(r2);
        double G[3], W, dW;
        K.eval(si, rr, W, dW);
        corr.gradient(i, r, W, dW / rr, G);
        const double V = m[j] / rho[j];
        for (int k = 0; k < d; ++k)
          for (int l = 0; l < d; ++l) g[3 * k + l] += V * (p.v[k][j] - p.v[k][i]) * G[l];
      }
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l) (*out[3 * k + l])[i] = g[3 * k + l];
    }
    return true;
  }

 private:
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_velocity_gradient(int dim) { return std::make_unique<VelocityGradient>(dim); }

}  // namespace sph
