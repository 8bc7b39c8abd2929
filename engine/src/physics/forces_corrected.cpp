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
#include "pair_fields.h"
#include "pair_terms.h"
#include "terms/visc_monaghan.h"
#include "viscous_stress.h"

namespace sph {
namespace {

/// The pair loop of the stress form: its fields, terms and the work per particle and per pair.
class StressLoop {
 public:
  StressLoop(StageContext& c, int dim, bool stress)
      : c_(c), f_(c.p), corr_(c.p), viscous_(c.p, dim, c.prm.visc.nu, stress), visc_(c),
        monaghan_(c.prm.physics.viscosity == ViscType::Monaghan), skip_walls_(!c.walls_in_sums()),
        alpha_scale_(monaghan_ ? visc_.alpha_scale : 1.0), beta_scale_(monaghan_ ? visc_.beta_scale : 1.0),
        support_(c.kernel.support()) {}

  /// dv_a/dt and v_sig of particle i, over its neighbours in list order.
  void particle(std::size_t i) const {
    Particles& p = c_.p;
    const Kernel::Scale si = c_.kernel.scale(f_.h[i]);
    double Ti[9];
    stress(i, Ti);
    for (double& t : Ti) t /= f_.rho[i] * f_.rho[i];
    double acc[3] = {0.0, 0.0, 0.0};
    double vs = f_.cs[i];
    for (std::uint32_t j : c_.nl.of(i)) {
      if (j == i) continue;
      if (skip_walls_ && p.kind[j]) continue;
      pair(i, j, si, Ti, acc, vs);
    }
    for (int k = 0; k < 3; ++k) p.a[k][i] = acc[k];
    f_.vsig[i] = vs;
  }

 private:
  /// T of particle b (3 x 3, row-major): -P I + 2 mu (D - tr D / 3 I)
  void stress(std::size_t b, double T[9]) const {
    for (int k = 0; k < 9; ++k) T[k] = 0.0;
    for (int k = 0; k < viscous_.d; ++k) T[4 * k] = -f_.P[b];
    if (viscous_.on()) viscous_.add(b, f_.rho[b], T);
  }

  /// Pair (i, j)'s term of dv_i/dt into acc and its signal speed into vs, if j is within support
  /// max(h_i, h_j); Ti = T_i / rho_i^2.
  void pair(std::size_t i, std::uint32_t j, const Kernel::Scale& si, const double Ti[9], double acc[3],
            double& vs) const {
    const Particles& p = c_.p;
    const double* rho = f_.rho;
    const double* cs = f_.cs;
    double r[3], mr[3], dv[3];
    for (int k = 0; k < 3; ++k) {
      r[k] = p.x[k][i] - p.x[k][j];
      mr[k] = -r[k];
      dv[k] = p.v[k][i] - p.v[k][j];
    }
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    const double hi = f_.h[i], hj = f_.h[j];
    const double R = support_ * std::max(hi, hj);
    if (r2 >= R * R || r2 == 0.0) return;
    const double rr = std::sqrt(r2), rinv = 1.0 / rr;
    double Wi, dWi, Wj, dWj;
    pair::kernels(c_.kernel, si, hi, hj, rr, Wi, dWi, Wj, dWj);
    double Gi[3], Gj[3], Tj[9];
    corr_.gradient(i, r, Wi, dWi * rinv, Gi);
    corr_.gradient(j, mr, Wj, dWj * rinv, Gj);
    stress(j, Tj);
    const double inv_rhoj2 = 1.0 / (rho[j] * rho[j]);
    const double vdotr = dv[0] * r[0] + dv[1] * r[1] + dv[2] * r[2];
    vs = std::max(vs, pair::signal_speed(cs[i], cs[j], vdotr * rinv, alpha_scale_, beta_scale_));
    const double Pi = monaghan_ ? pair::monaghan_pi(vdotr, r2, hi, hj, rho[i], rho[j], cs[i], cs[j], visc_.alpha,
                                                    visc_.beta, visc_.eps)
                                : 0.0;
    for (int k = 0; k < viscous_.d; ++k) {
      double t = 0.0;
      for (int l = 0; l < viscous_.d; ++l) t += Ti[3 * k + l] * Gi[l] - Tj[3 * k + l] * inv_rhoj2 * Gj[l];
      acc[k] += f_.m[j] * (t - Pi * 0.5 * (Gi[k] - Gj[k]));
    }
  }

  StageContext& c_;
  const ForceFields f_;
  const CorrectionFields corr_;
  const ViscousStress viscous_;
  const terms::ViscMonaghan visc_;  // constant alpha: visc.switch is refused with this form (Physics::validate)
  bool monaghan_, skip_walls_;
  double alpha_scale_, beta_scale_, support_;
};

class ForcesCorrected final : public Stage {
 public:
  ForcesCorrected(const Physics& ph, int dim)
      : Stage({.name = "forces: corrected (stress form)",
               .needs = {Field::Mass, Field::Density, Field::H, Field::Pressure, Field::SoundSpeed},
               .writes = {Field::SignalSpeed}}),
        stress_(ph.viscosity == ViscType::Laplacian), dim_(dim) {}
  bool sets_acceleration() const override { return true; }
  bool reads_every_list() const override { return false; }  // the pair loop visits the active rows

  bool run(StageContext& c) override {
    const StressLoop loop(c, dim_, stress_);
    const std::size_t n = c.p.fluid();
#pragma omp parallel for schedule(static) if (c.p.size() >= kParallelMin)
    for (std::size_t k = 0; k < c.rows(n); ++k) loop.particle(c.row(k));
    return true;
  }

  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }
  void dt_limits(const StageContext& c, std::span<double> dt) const override { courant_limits(c.p, dt); }

 private:
  bool stress_;
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_corrected(const Physics& ph, int dim) {
  return std::make_unique<ForcesCorrected>(ph, dim);
}

}  // namespace sph
