// "Standard-corrected" SPH (seed 001 eqs. 53-55): the standard momentum equation with the corrected
// kernel gradients G of corrected_kernel.h, barotropic (no energy equation):
//   dv_a/dt = -sum_b m_b [P_a/rho_a^2 G_a(b) - P_b/rho_b^2 G_b(a) + Pi_ab (G_a(b) - G_b(a))/2]
// Seed 001 eq. 53 evaluates one corrected gradient, at the neighbour; the pair form above (Bonet & Lok
// 1999, §5) is antisymmetric in a and b, so linear momentum is conserved to round-off, and it reduces to
// the standard eq. 44 when L = I and S = 1. The Laplacian viscosity uses r . (G_a(b) - G_b(a))/2.
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "core/stages.h"
#include "corrected_kernel.h"
#include "courant.h"
#include "continuity_output.h"
#include "pair_terms.h"

namespace sph {
namespace {

/// Cont: also the continuity rate drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . G_a(b) (seed 001 eq. 54;
/// density_continuity.cpp), in the same pass.
template <int D, ViscType V, bool Cont, bool Xsph>
void standard_corrected_loop(StageContext& c, std::vector<double>& pr2, std::vector<double>& vol) {
  const Kernel& K = c.kernel;
  const Params& prm = c.prm;
  Particles& p = c.p;
  const std::size_t n = p.fluid();
  const double* m = p[Field::Mass].data();
  const double* rho = p[Field::Density].data();
  const double* h = p[Field::H].data();
  const double* P = p[Field::Pressure].data();
  const double* cs = p[Field::SoundSpeed].data();
  double* vsig = p[Field::SignalSpeed].data();
  const double* x[D];
  const double* v[D];
  for (int k = 0; k < D; ++k) { x[k] = p.x[k].data(); v[k] = p.v[k].data(); }
  const std::uint8_t* kind = p.kind.data();
  const CorrectionFields corr(p);
  // per-particle factors, once per evaluation: P/rho^2 and V = m/rho (ghosts included)
  const std::size_t total = p.total();
  pr2.resize(total);
  vol.resize(total);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t j = 0; j < total; ++j) {
    pr2[j] = P[j] / (rho[j] * rho[j]);
    vol[j] = m[j] / rho[j];
  }
  std::unique_ptr<ContinuityOutput> cont;
  if constexpr (Cont) cont = std::make_unique<ContinuityOutput>(p, prm);
  const double* dvx[D] = {};
  if constexpr (Xsph)
    for (int k = 0; k < D; ++k) dvx[k] = p[component(Field::XsphX, k)].data();
  double sum_nb = 0.0;
  const bool skip_walls = !c.walls_in_sums();
  const double alpha = prm.visc.alpha, beta = prm.visc.beta, eps = prm.visc.eps, nu = prm.visc.nu;
  const double alpha_scale = V == ViscType::Monaghan ? std::max(1.0, alpha) : 1.0;
  const double beta_scale = V == ViscType::Monaghan ? std::max(1.0, 0.5 * beta) : 1.0;
  const double support = K.support();
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : sum_nb) if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double hi = h[i], Ri2 = support * support * hi * hi;
    const Kernel::Scale si = K.scale(hi);
    const double Ai = pr2[i];
    double acc[D] = {};
    double vs = cs[i], drho = 0.0, diff = 0.0;
    int count = 1;
    for (std::uint32_t j : c.nl.of(i)) {
      if (j == i) continue;
      if (skip_walls && kind[j]) continue;
      double r[D], mr[D], dv[D];
      double r2 = 0.0, vdotr = 0.0;
      for (int k = 0; k < D; ++k) {
        r[k] = x[k][i] - x[k][j];
        mr[k] = -r[k];
        dv[k] = v[k][i] - v[k][j];
        r2 += r[k] * r[k];
        vdotr += dv[k] * r[k];
      }
      const double hj = h[j];
      const double R = support * std::max(hi, hj);
      if (r2 >= R * R || r2 == 0.0) continue;
      const double rr = std::sqrt(r2), rinv = 1.0 / rr;
      double Wi, dWi, Wj, dWj;
      pair::kernels(K, si, hi, hj, rr, Wi, dWi, Wj, dWj);
      double Gi[D], Gj[D];
      corr.gradient_d<D>(i, r, Wi, dWi * rinv, Gi);
      corr.gradient_d<D>(j, mr, Wj, dWj * rinv, Gj);
      const double Aj = pr2[j];
      if constexpr (Cont) {
        if (r2 < Ri2) ++count;
        double dot = 0.0;
        for (int k = 0; k < D; ++k) {
          double d = dv[k];
          if constexpr (Xsph) d += dvx[k][i] - (kind[j] ? 0.0 : dvx[k][j]);
          dot += d * Gi[k];
        }
        drho += vol[j] * dot;
        diff += pair::density_diffusion(vol[j], rho[i], rho[j], dWi * rinv);
      }
      vs = std::max(vs, pair::signal_speed(cs[i], cs[j], vdotr * rinv, alpha_scale, beta_scale));
      double Pi = 0.0;
      if constexpr (V == ViscType::Monaghan)
        Pi = pair::monaghan_pi(vdotr, r2, hi, hj, rho[i], rho[j], cs[i], cs[j], alpha, beta, eps);
      double rdG = 0.0;
      for (int k = 0; k < D; ++k) {
        const double Gm = 0.5 * (Gi[k] - Gj[k]);
        acc[k] -= m[j] * (Ai * Gi[k] - Aj * Gj[k] + Pi * Gm);
        rdG += r[k] * Gm;
      }
      if constexpr (V == ViscType::Laplacian) {
        const double f = pair::laplacian_factor(m[j], nu, rho[i], rho[j], rdG, r2, 0.5 * (hi + hj), eps);
        for (int k = 0; k < D; ++k) acc[k] += f * dv[k];
      }
    }
    for (int k = 0; k < D; ++k) p.a[k][i] = acc[k];
    for (int k = D; k < 3; ++k) p.a[k][i] = 0.0;
    vsig[i] = vs;
    if constexpr (Cont) {
      cont->store(i, rho[i], hi, drho, diff, count);
      sum_nb += count;
    }
  }
  if constexpr (Cont) ContinuityOutput::finish(c, sum_nb, n);
}

template <int D, bool Cont, bool Xsph>
void dispatch_visc(StageContext& c, std::vector<double>& pr2, std::vector<double>& vol) {
  switch (c.prm.physics.viscosity) {
    case ViscType::None: standard_corrected_loop<D, ViscType::None, Cont, Xsph>(c, pr2, vol); break;
    case ViscType::Monaghan: standard_corrected_loop<D, ViscType::Monaghan, Cont, Xsph>(c, pr2, vol); break;
    case ViscType::Laplacian: standard_corrected_loop<D, ViscType::Laplacian, Cont, Xsph>(c, pr2, vol); break;
  }
}

template <int D>
void dispatch(StageContext& c, bool cont, bool xsph, std::vector<double>& pr2, std::vector<double>& vol) {
  if (!cont) dispatch_visc<D, false, false>(c, pr2, vol);
  else if (xsph) dispatch_visc<D, true, true>(c, pr2, vol);
  else dispatch_visc<D, true, false>(c, pr2, vol);
}

class ForcesStandardCorrected final : public Stage {
 public:
  ForcesStandardCorrected(const Physics& ph, int dim)
      : dim_(dim), cont_(fuses_continuity(ph)), xsph_(ph.xsph == Toggle::On) {}
  std::string_view name() const override { return "forces: standard-corrected"; }
  FieldSet needs() const override {
    return FieldSet{}.add(Field::Mass).add(Field::Density).add(Field::H).add(Field::Pressure).add(Field::SoundSpeed);
  }
  FieldSet writes() const override {
    FieldSet f;
    f.add(Field::SignalSpeed);
    if (cont_) f.add(Field::DensityRate).add(Field::Neighbours);
    return f;
  }
  bool sets_acceleration() const override { return true; }
  bool run(StageContext& c) override {
    switch (dim_) {
      case 1: dispatch<1>(c, cont_, xsph_, pr2_, vol_); break;
      case 2: dispatch<2>(c, cont_, xsph_, pr2_, vol_); break;
      default: dispatch<3>(c, cont_, xsph_, pr2_, vol_); break;
    }
    return true;
  }
  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }

 private:
  int dim_;
  bool cont_, xsph_;
  std::vector<double> pr2_, vol_;  ///< per-particle P/rho^2 and m/rho, reused between evaluations
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard_corrected(const Physics& ph, int dim) {
  return std::make_unique<ForcesStandardCorrected>(ph, dim);
}

}  // namespace sph
