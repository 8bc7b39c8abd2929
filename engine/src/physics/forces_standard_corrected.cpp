// "Standard-corrected" SPH (seed 001 eqs. 53-55): the standard momentum equation with the corrected
// kernel gradients G of corrected_kernel.h, barotropic (no energy equation):
//   dv_a/dt = -sum_b m_b [P_a/rho_a^2 G_a(b) - P_b/rho_b^2 G_b(a) + Pi_ab (G_a(b) - G_b(a))/2]
// Seed 001 eq. 53 evaluates one corrected gradient, at the neighbour; the pair form above (Bonet & Lok
// 1999, §5) is antisymmetric in a and b, so linear momentum is conserved to round-off, and it reduces to
// the standard eq. 44 when L = I and S = 1. The Laplacian viscosity uses r . (G_a(b) - G_b(a))/2.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "corrected_kernel.h"
#include "courant.h"
#include "pair_terms.h"

namespace sph {
namespace {

class ForcesStandardCorrected final : public Stage {
 public:
  explicit ForcesStandardCorrected(int dim) : dim_(dim) {}
  std::string_view name() const override { return "forces: standard-corrected"; }
  FieldSet needs() const override {
    return FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::H).add(Field::Pressure).add(Field::SoundSpeed);
  }
  FieldSet writes() const override { return FieldSet{}.add(Field::SignalSpeed); }
  bool sets_acceleration() const override { return true; }

  bool run(StageContext& c) override {
    const Kernel& K = c.kernel;
    const Params& prm = c.prm;
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    const auto& rho = p[Field::Density];
    const auto& h = p[Field::H];
    const auto& P = p[Field::Pressure];
    const auto& cs = p[Field::SoundSpeed];
    auto& vsig = p[Field::SignalSpeed];
    const CorrectionFields corr(p);
    const ViscType visc = prm.physics.viscosity;
    const bool skip_walls = !c.walls_in_sums();
    const double alpha = prm.visc.alpha, beta = prm.visc.beta, eps = prm.visc.eps, nu = prm.visc.nu;
    const double alpha_scale = visc == ViscType::Monaghan ? std::max(1.0, alpha) : 1.0;
    const double beta_scale = visc == ViscType::Monaghan ? std::max(1.0, 0.5 * beta) : 1.0;
    const double support = K.support();
    const int d = dim_;
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const double hi = h[i];
      const double Ai = P[i] / (rho[i] * rho[i]);
      double acc[3] = {0.0, 0.0, 0.0};
      double vs = cs[i];
      for (std::uint32_t j : c.nl.of(i)) {
        if (j == i) continue;
        if (skip_walls && p.kind[j]) continue;
        double r[3], mr[3], dv[3];
        for (int k = 0; k < 3; ++k) {
          r[k] = p.x[k][i] - p.x[k][j];
          mr[k] = -r[k];
          dv[k] = p.v[k][i] - p.v[k][j];
        }
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        const double hj = h[j];
        const double R = support * std::max(hi, hj);
        if (r2 >= R * R || r2 == 0.0) continue;
        const double rr = std::sqrt(r2), rinv = 1.0 / rr;
        double Gi[3], Gj[3];
        corr.gradient(i, r, K.W(rr, hi), K.dWdr(rr, hi), rinv, Gi);
        corr.gradient(j, mr, K.W(rr, hj), K.dWdr(rr, hj), rinv, Gj);
        const double Aj = P[j] / (rho[j] * rho[j]);
        const double vdotr = dv[0] * r[0] + dv[1] * r[1] + dv[2] * r[2];
        vs = std::max(vs, pair::signal_speed(cs[i], cs[j], vdotr * rinv, alpha_scale, beta_scale));
        const double Pi = visc == ViscType::Monaghan
                              ? pair::monaghan_pi(vdotr, r2, hi, hj, rho[i], rho[j], cs[i], cs[j], alpha, beta, eps)
                              : 0.0;
        double rdG = 0.0;
        for (int k = 0; k < d; ++k) {
          const double Gm = 0.5 * (Gi[k] - Gj[k]);
          acc[k] -= m[j] * (Ai * Gi[k] - Aj * Gj[k] + Pi * Gm);
          rdG += r[k] * Gm;
        }
        if (visc == ViscType::Laplacian) {
          const double f = pair::laplacian_factor(m[j], nu, rho[i], rho[j], rdG, r2, 0.5 * (hi + hj), eps);
          for (int k = 0; k < d; ++k) acc[k] += f * dv[k];
        }
      }
      for (int k = 0; k < 3; ++k) p.a[k][i] = acc[k];
      vsig[i] = vs;
    }
    return true;
  }

  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }

 private:
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard_corrected(const Physics&, int dim) {
  return std::make_unique<ForcesStandardCorrected>(dim);
}

}  // namespace sph
