// Corrected SPH (seed 001 eqs. 48-52): the momentum equation as the divergence of the Cauchy stress
// T = -P I + 2 mu (D - tr D / 3 I), mu = rho nu, with corrected kernel gradients G (corrected_kernel.h)
// and D from the corrected velocity gradient (eq. 52) when physics.viscosity = laplacian:
//   dv_a/dt = sum_b m_b [T_a/rho_a^2 . G_a(b) - T_b/rho_b^2 . G_b(a)]
// Seed 001 eq. 48 writes the collocation form (1/rho_a) sum_b V_b T_b . G_a(b); tried here on the
// elliptical drop (dx = 0.025) it is violently unstable: E_kin grew from 7.9e6 to 1e38-1e58 J/m within
// 2 ms with any of alpha = 0.1-0.5, XSPH or a Laplacian viscosity (the collocation gradient and the
// continuity divergence are not adjoint, so nothing bounds the energy). The pairwise form above (Bonet
// & Lok 1999, §5) is antisymmetric in a and b, so it conserves linear momentum, and with the continuity
// equation it conserves energy to O(rho_a/rho_b - 1); it is exact for linear stress fields where L is
// exact. Seed 001 eq. 51 prints T = +P I + ..., against its own eq. 2 (T = -P I + ...): the physical sign
// is used. With physics.viscosity = monaghan, Pi_ab acts as the pair term -sum_b m_b Pi_ab (G_a(b) -
// G_b(a))/2, as in the standard-corrected form.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "corrected_kernel.h"
#include "courant.h"
#include "pair_terms.h"
#include "terms/visc_monaghan.h"

namespace sph {
namespace {

class ForcesCorrected final : public Stage {
 public:
  ForcesCorrected(const Physics& ph, int dim) : stress_(ph.viscosity == ViscType::Laplacian), dim_(dim) {}
  std::string_view name() const override { return "forces: corrected (stress form)"; }
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
    const int d = dim_;
    const std::vector<double>* grad[9] = {};
    if (stress_)
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l) grad[3 * k + l] = &p[component(Field::VelGradXX, k, l)];
    const bool monaghan = prm.physics.viscosity == ViscType::Monaghan;
    const bool skip_walls = !c.walls_in_sums();
    const double nu = prm.visc.nu;
    const terms::ViscMonaghan visc(c);  // constant alpha: visc.switch is refused with this form (Physics::validate)
    const double alpha_scale = monaghan ? visc.alpha_scale : 1.0;
    const double beta_scale = monaghan ? visc.beta_scale : 1.0;
    const double support = K.support();
    // T of particle b (3 x 3, row-major): -P I + 2 mu (D - tr D / 3 I)
    auto stress = [&](std::size_t b, double T[9]) {
      for (int k = 0; k < 9; ++k) T[k] = 0.0;
      for (int k = 0; k < d; ++k) T[4 * k] = -P[b];
      if (!stress_) return;
      const double mu = rho[b] * nu;
      double tr = 0.0;
      for (int k = 0; k < d; ++k) tr += (*grad[4 * k])[b];
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l) {
          const double D = 0.5 * ((*grad[3 * k + l])[b] + (*grad[3 * l + k])[b]);
          T[3 * k + l] += 2.0 * mu * (D - (k == l ? tr / 3.0 : 0.0));
        }
    };
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const double hi = h[i];
      const Kernel::Scale si = K.scale(hi);
      double Ti[9], Tj[9];
      stress(i, Ti);
      for (double& t : Ti) t /= rho[i] * rho[i];
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
        double Wi, dWi, Wj, dWj;
        pair::kernels(K, si, hi, hj, rr, Wi, dWi, Wj, dWj);
        double Gi[3], Gj[3];
        corr.gradient(i, r, Wi, dWi * rinv, Gi);
        corr.gradient(j, mr, Wj, dWj * rinv, Gj);
        stress(j, Tj);
        const double inv_rhoj2 = 1.0 / (rho[j] * rho[j]);
        const double vdotr = dv[0] * r[0] + dv[1] * r[1] + dv[2] * r[2];
        vs = std::max(vs, pair::signal_speed(cs[i], cs[j], vdotr * rinv, alpha_scale, beta_scale));
        const double Pi = monaghan ? pair::monaghan_pi(vdotr, r2, hi, hj, rho[i], rho[j], cs[i], cs[j], visc.alpha,
                                                       visc.beta, visc.eps)
                                   : 0.0;
        for (int k = 0; k < d; ++k) {
          double t = 0.0;
          for (int l = 0; l < d; ++l) t += Ti[3 * k + l] * Gi[l] - Tj[3 * k + l] * inv_rhoj2 * Gj[l];
          acc[k] += m[j] * (t - Pi * 0.5 * (Gi[k] - Gj[k]));
        }
      }
      for (int k = 0; k < 3; ++k) p.a[k][i] = acc[k];
      vsig[i] = vs;
    }
    return true;
  }

  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }

 private:
  bool stress_;
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_corrected(const Physics& ph, int dim) {
  return std::make_unique<ForcesCorrected>(ph, dim);
}

}  // namespace sph
