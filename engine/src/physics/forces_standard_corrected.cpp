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
#include "pair_block.h"
#include "pair_terms.h"
#include "sph/kernel_shapes.h"
#include "terms/visc_terms.h"

namespace sph {
namespace {

/// The per-pair columns of the loop's PairBlock.
enum Column { kT0, kT1, kT2, kL0, kL1, kL2, kVs, kDrho, kDiff, kCount, kColumns };

/// Per-particle factors, once per evaluation (ghosts included): P/rho^2, V = m/rho and the kernel's
/// factors of h (Kernel::scale). Kept between evaluations (no reallocation).
struct Factors {
  std::vector<double> pr2, vol, hinv, wnorm, dwnorm, R2;
};

/// Cont: also the continuity rate drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . G_a(b) (seed 001 eq. 54;
/// density_continuity.cpp), in the same pass. In three passes (pair_block.h): the interacting pairs,
/// their terms (vectorised; the kernel's shape fixed at compile time), the sums in list order.
template <int D, class V, bool Cont, bool Xsph, class Shape>
void standard_corrected_loop(StageContext& c, const Shape& shape, Factors& fac) {
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
  const double* v[3] = {p.v[0].data(), p.v[1].data(), p.v[2].data()};
  const std::uint8_t* kind = p.kind.data();
  const CorrectionFields corr(p);
  const std::size_t total = p.total();
  const double support = K.support();
  fac.pr2.resize(total);
  fac.vol.resize(total);
  fac.hinv.resize(total);
  fac.wnorm.resize(total);
  fac.dwnorm.resize(total);
  fac.R2.resize(total);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t j = 0; j < total; ++j) {
    fac.pr2[j] = P[j] / (rho[j] * rho[j]);
    fac.vol[j] = m[j] / rho[j];
    const Kernel::Scale s = K.scale(h[j]);
    fac.hinv[j] = s.hinv;
    fac.wnorm[j] = s.w_norm;
    fac.dwnorm[j] = s.dw_norm;
    const double R = support * h[j];
    fac.R2[j] = R * R;  // pairs within support max(h_i, h_j)
  }
  const double* pr2 = fac.pr2.data();
  const double* vol = fac.vol.data();
  const double* hinv = fac.hinv.data();
  const double* wnorm = fac.wnorm.data();
  const double* dwnorm = fac.dwnorm.data();
  std::unique_ptr<ContinuityOutput> cont;
  if constexpr (Cont) cont = std::make_unique<ContinuityOutput>(p, prm);
  const double* dvx[3] = {};
  if constexpr (Xsph)
    for (int k = 0; k < D; ++k) dvx[k] = p[component(Field::XsphX, k)].data();
  double sum_nb = 0.0;
  const bool skip_walls = !c.walls_in_sums();
  const V visc(c);  // the viscosity term (terms/visc_*.h)
#pragma omp parallel reduction(+ : sum_nb) if (p.size() >= kParallelMin)
  {
  PairBlock<kColumns> b;  // this thread's pairs of i
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
  for (std::size_t i = 0; i < n; ++i) {
    const double hi = h[i], Ri2 = support * support * hi * hi;
    const double Ai = pr2[i], rhoi = rho[i], csi = cs[i];
    const double hinv_i = hinv[i], wn_i = wnorm[i], dwn_i = dwnorm[i];
    double ci[D], Ai_[D][D], vi[D], xsi[D];
    for (int k = 0; k < D; ++k) {
      ci[k] = corr.c[k][i];
      vi[k] = v[k][i];
      xsi[k] = Xsph ? dvx[k][i] : 0.0;
      for (int l = 0; l < D; ++l) Ai_[k][l] = corr.A[3 * k + l][i];
    }
    const std::size_t np = gather_pairs(p, fac.R2.data(), i, c.nl.of(i), skip_walls, b);
    const std::uint32_t* J = b.j.data();
    const double* RX[3] = {b.dx.data(), b.dy.data(), b.dz.data()};
    const double* cj[D];
    const double* Aj_[D][D];
    for (int q = 0; q < D; ++q) {
      cj[q] = corr.c[q];
      for (int l = 0; l < D; ++l) Aj_[q][l] = corr.A[3 * q + l];
    }
    const double* R2 = b.r2.data();
    double* T[3] = {b[kT0], b[kT1], b[kT2]};
    double* L[3] = {b[kL0], b[kL1], b[kL2]};
    double* VS = b[kVs];
    double* DR = b[kDrho];
    double* DF = b[kDiff];
    double* CN = b[kCount];
#pragma omp simd
    for (std::size_t k = 0; k < np; ++k) {
      const std::uint32_t j = J[k];
      const double r2 = R2[k];
      double r[D], dv[D];
      double vdotr = 0.0;
      for (int q = 0; q < D; ++q) {
        r[q] = RX[q][k];
        dv[q] = vi[q] - v[q][j];
        vdotr += dv[q] * r[q];
      }
      const double hj = h[j];
      const double rr = std::sqrt(r2), rinv = 1.0 / rr;
      const double qi = rr * hinv_i, qj = rr * hinv[j];
      const double Wi = wn_i * shape.w(qi), dWi = dwn_i * shape.dw(qi);
      const double Wj = wnorm[j] * shape.w(qj), dWj = dwnorm[j] * shape.dw(qj);
      // G_a(b) and G_b(a) (corrected_kernel.h), with r = x_a - x_b and -r
      const double dWi_r = dWi * rinv, dWj_r = dWj * rinv;
      double Gi[D], Gj[D];
      for (int q = 0; q < D; ++q) {
        double gi = -Wi * ci[q], gj = -Wj * cj[q][j];
        for (int l = 0; l < D; ++l) {
          gi += Ai_[q][l] * r[l] * dWi_r;
          gj += Aj_[q][l][j] * (-r[l]) * dWj_r;
        }
        Gi[q] = gi;
        Gj[q] = gj;
      }
      const double Aj = pr2[j];
      if constexpr (Cont) {
        CN[k] = r2 < Ri2 ? 1.0 : 0.0;
        double dot = 0.0;
        for (int q = 0; q < D; ++q) {
          double d = dv[q];
          if constexpr (Xsph) {
            const double xj = dvx[q][j];  // loaded whatever the kind: no branch in the vectorised loop
            d += xsi[q] - (kind[j] ? 0.0 : xj);
          }
          dot += d * Gi[q];
        }
        DR[k] = vol[j] * dot;
        DF[k] = pair::density_diffusion(vol[j], rhoi, rho[j], dWi * rinv);
      }
      VS[k] = pair::signal_speed(csi, cs[j], vdotr * rinv, visc.alpha_scale, visc.beta_scale);
      double Pi = 0.0;
      if constexpr (V::kPi) Pi = visc.pi(i, j, vdotr, r2, hi, hj, rhoi, rho[j], csi, cs[j]);
      double rdG = 0.0;
      for (int q = 0; q < D; ++q) {
        const double Gm = 0.5 * (Gi[q] - Gj[q]);
        T[q][k] = m[j] * (Ai * Gi[q] - Aj * Gj[q] + Pi * Gm);
        rdG += r[q] * Gm;
      }
      if constexpr (V::kLaplacian) {
        const double f = visc.factor(m[j], rhoi, rho[j], rdG, r2, 0.5 * (hi + hj));
        for (int q = 0; q < D; ++q) L[q][k] = f * dv[q];
      }
    }
    // the sums, in list order
    double acc[D] = {};
    double vs = csi, drho = 0.0, diff = 0.0;
    int count = 1;
    for (std::size_t k = 0; k < np; ++k) {
      for (int q = 0; q < D; ++q) {
        acc[q] -= T[q][k];
        if constexpr (V::kLaplacian) acc[q] += L[q][k];
      }
      vs = std::max(vs, VS[k]);
      if constexpr (Cont) {
        count += static_cast<int>(CN[k]);
        drho += DR[k];
        diff += DF[k];
      }
    }
    for (int k = 0; k < D; ++k) p.a[k][i] = acc[k];
    for (int k = D; k < 3; ++k) p.a[k][i] = 0.0;
    vsig[i] = vs;
    if constexpr (Cont) {
      cont->store(i, rhoi, hi, drho, diff, count);
      sum_nb += count;
    }
  }
  }
  if constexpr (Cont) ContinuityOutput::finish(c, sum_nb, n);
}

template <int D, bool Cont, bool Xsph, class Shape>
void dispatch_visc(StageContext& c, const Shape& s, Factors& f) {
  terms::with_viscosity(c.prm.physics, [&](auto tag) {
    standard_corrected_loop<D, typename decltype(tag)::type, Cont, Xsph>(c, s, f);
  });
}

template <int D>
void dispatch(StageContext& c, bool cont, bool xsph, Factors& f) {
  // the kernel shape is chosen once here, not per pair
  shape::with_shape(c.kernel.type(), D, [&](auto s) {
    if (!cont) dispatch_visc<D, false, false>(c, s, f);
    else if (xsph) dispatch_visc<D, true, true>(c, s, f);
    else dispatch_visc<D, true, false>(c, s, f);
  });
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
      case 1: dispatch<1>(c, cont_, xsph_, factors_); break;
      case 2: dispatch<2>(c, cont_, xsph_, factors_); break;
      default: dispatch<3>(c, cont_, xsph_, factors_); break;
    }
    return true;
  }
  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }

 private:
  int dim_;
  bool cont_, xsph_;
  Factors factors_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard_corrected(const Physics& ph, int dim) {
  return std::make_unique<ForcesStandardCorrected>(ph, dim);
}

}  // namespace sph
