// The standard-corrected force loop's work for one particle a (forces_standard_corrected.cpp states the
// equations), in the passes of pair_block.h: per pair the kernel and the corrected gradients G_a(b),
// G_b(a), then the momentum and continuity terms (vectorised, no reductions); the sums in list order;
// the write-back of dv/dt, v_sig and the fused continuity rate.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/parallel.h"
#include "core/stage.h"
#include "continuity_output.h"
#include "corrected_kernel.h"
#include "pair_block.h"
#include "pair_fields.h"
#include "pair_terms.h"

namespace sph::standard_corrected {

/// The per-pair columns of the loop's PairBlock.
enum Column { kT0, kT1, kT2, kL0, kL1, kL2, kVs, kDrho, kDiff, kCount, kColumns };
using Block = PairBlock<kColumns>;

/// Per-particle factors, once per evaluation (ghosts included): P/rho^2, V = m/rho and the kernel's
/// factors of h (Kernel::scale). Kept between evaluations (no reallocation).
struct Factors {
  std::vector<double> pr2, vol, hinv, wnorm, dwnorm, R2;

  void compute(Particles& p, const Kernel& K) {
    const ForceFields f(p);
    const std::size_t total = p.total();
    pr2.resize(total);
    vol.resize(total);
    hinv.resize(total);
    wnorm.resize(total);
    dwnorm.resize(total);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t j = 0; j < total; ++j) {
      pr2[j] = pressure_factor(f.P[j], 1.0, f.rho[j]);
      vol[j] = f.m[j] / f.rho[j];
      const Kernel::Scale s = K.scale(f.h[j]);
      hinv[j] = s.hinv;
      wnorm[j] = s.w_norm;
      dwnorm[j] = s.dw_norm;
    }
    support_radii2(p, K.support(), R2);  // pairs within support max(h_i, h_j)
  }
};

/// A block's columns, taken once before the pair loops.
struct Columns {
  double *T[3], *L[3], *VS, *DR, *DF, *CN;
  explicit Columns(Block& b)
      : T{b[kT0], b[kT1], b[kT2]}, L{b[kL0], b[kL1], b[kL2]}, VS(b[kVs]), DR(b[kDrho]), DF(b[kDiff]),
        CN(b[kCount]) {}
};

/// Particle a's own values, loaded once for its pairs: its correction c_a and A_a (corrected_kernel.h),
/// velocity and XSPH correction.
template <int D>
struct Self {
  std::size_t i;
  double h, Ri2, A, rho, cs, hinv, wn, dwn;
  double c[D], Ac[D][D], v[D], xs[D];
};

/// The kernel and geometry of pair (a, j): r_aj, v_aj, v_aj . r_aj, 1/|r|, dW/dr(h_a) and the
/// corrected gradients G_a(j), G_j(a).
template <int D>
struct Geometry {
  std::uint32_t j;
  double r2, r[D], dv[D], vdotr, rinv, dWi, Gi[D], Gj[D];
};

/// The sums over a's pairs.
template <int D>
struct Sums {
  double acc[D] = {};
  double vs = 0.0, drho = 0.0, diff = 0.0;
  int count = 1;
};

/// V: the viscosity term (terms/visc_*.h); Cont: the continuity rate in the same pass, with the XSPH
/// velocity v* when Xsph.
template <int D, class V, bool Cont, bool Xsph, class Shape>
struct Pairs {
  using Block = standard_corrected::Block;
  static constexpr int kColumns = standard_corrected::kColumns;
  static constexpr bool kThreeD = true;  // the block's dz is filled in every dimension (read for q < D only)
  static constexpr bool kCont = Cont;
  const Shape shape;
  const V visc;
  const ForceFields f;
  const CorrectionFields corr;
  const double *pr2, *vol, *hinv, *wnorm, *dwnorm;
  const double* v[3];
  const double* dvx[3] = {};  ///< XSPH corrections v* - v
  const double* cj[D];        ///< c of every particle, per component
  const double* Aj_[D][D];    ///< A of every particle, per component
  const std::uint8_t* kind;
  double* a[3];
  double support;

  Pairs(StageContext& c, const Shape& s, const Factors& fac)
      : shape(s), visc(c), f(c.p), corr(c.p), pr2(fac.pr2.data()), vol(fac.vol.data()), hinv(fac.hinv.data()),
        wnorm(fac.wnorm.data()), dwnorm(fac.dwnorm.data()), v{c.p.v[0].data(), c.p.v[1].data(), c.p.v[2].data()},
        kind(c.p.kind.data()), a{c.p.a[0].data(), c.p.a[1].data(), c.p.a[2].data()},
        support(c.kernel.support()) {
    if constexpr (Xsph)
      for (int k = 0; k < D; ++k) dvx[k] = c.p[component(Field::XsphX, k)].data();
    for (int q = 0; q < D; ++q) {
      cj[q] = corr.c[q];
      for (int l = 0; l < D; ++l) Aj_[q][l] = corr.A[3 * q + l];
    }
  }

  Self<D> self(std::size_t i) const {
    Self<D> s;
    s.i = i;
    s.h = f.h[i];
    s.Ri2 = support * support * s.h * s.h;
    s.A = pr2[i];
    s.rho = f.rho[i];
    s.cs = f.cs[i];
    s.hinv = hinv[i];
    s.wn = wnorm[i];
    s.dwn = dwnorm[i];
    for (int k = 0; k < D; ++k) {
      s.c[k] = corr.c[k][i];
      s.v[k] = v[k][i];
      s.xs[k] = Xsph ? dvx[k][i] : 0.0;
      for (int l = 0; l < D; ++l) s.Ac[k][l] = corr.A[3 * k + l][i];
    }
    return s;
  }

  /// The pair's geometry and kernel, and G_a(b), G_b(a) (corrected_kernel.h) with r = x_a - x_b and -r.
  [[gnu::always_inline]] Geometry<D> geometry(const Self<D>& s, std::uint32_t j, const double* const RX[3],
                                              double r2, std::size_t k) const {
    Geometry<D> g;
    g.j = j;
    g.r2 = r2;
    g.vdotr = 0.0;
    for (int q = 0; q < D; ++q) {
      g.r[q] = RX[q][k];
      g.dv[q] = s.v[q] - v[q][j];
      g.vdotr += g.dv[q] * g.r[q];
    }
    const double rr = std::sqrt(g.r2);
    g.rinv = 1.0 / rr;
    const double qi = rr * s.hinv, qj = rr * hinv[j];
    const double Wi = s.wn * shape.w(qi), Wj = wnorm[j] * shape.w(qj), dWj = dwnorm[j] * shape.dw(qj);
    g.dWi = s.dwn * shape.dw(qi);
    const double dWi_r = g.dWi * g.rinv, dWj_r = dWj * g.rinv;
    for (int q = 0; q < D; ++q) {
      double gi = -Wi * s.c[q], gj = -Wj * cj[q][j];
      for (int l = 0; l < D; ++l) {
        gi += s.Ac[q][l] * g.r[l] * dWi_r;
        gj += Aj_[q][l][j] * (-g.r[l]) * dWj_r;
      }
      g.Gi[q] = gi;
      g.Gj[q] = gj;
    }
    return g;
  }

  /// The pair's share of the continuity rate, V_j (v*_a - v*_j) . G_a(j), its density diffusion and
  /// whether j is within a's own support.
  [[gnu::always_inline]] void continuity(const Self<D>& s, const Geometry<D>& g, const Columns& o,
                                         std::size_t k) const {
    const std::uint32_t j = g.j;
    o.CN[k] = g.r2 < s.Ri2 ? 1.0 : 0.0;
    double dot = 0.0;
    for (int q = 0; q < D; ++q) {
      double d = g.dv[q];
      if constexpr (Xsph) {
        const double xj = dvx[q][j];  // loaded whatever the kind: no branch in the vectorised loop
        d += s.xs[q] - (kind[j] ? 0.0 : xj);
      }
      dot += d * g.Gi[q];
    }
    o.DR[k] = vol[j] * dot;
    o.DF[k] = pair::density_diffusion(vol[j], s.rho, f.rho[j], g.dWi * g.rinv);
  }

  /// The pair's dv_a/dt terms (pressure and Pi; the Laplacian viscosity apart) and signal speed.
  [[gnu::always_inline]] void momentum(const Self<D>& s, const Geometry<D>& g, const Columns& o,
                                       std::size_t k) const {
    const std::uint32_t j = g.j;
    o.VS[k] = pair::signal_speed(s.cs, f.cs[j], g.vdotr * g.rinv, visc.alpha_scale, visc.beta_scale);
    double Pi = 0.0;
    if constexpr (V::kPi) Pi = visc.pi(s.i, j, g.vdotr, g.r2, s.h, f.h[j], s.rho, f.rho[j], s.cs, f.cs[j]);
    const double Aj = pr2[j];
    double rdG = 0.0;
    for (int q = 0; q < D; ++q) {
      const double Gm = 0.5 * (g.Gi[q] - g.Gj[q]);
      o.T[q][k] = f.m[j] * (s.A * g.Gi[q] - Aj * g.Gj[q] + Pi * Gm);
      rdG += g.r[q] * Gm;
    }
    if constexpr (V::kLaplacian) {
      const double fl = visc.factor(j, f.m[j], s.rho, f.rho[j], rdG, g.r2, 0.5 * (s.h + f.h[j]));
      for (int q = 0; q < D; ++q) o.L[q][k] = fl * g.dv[q];
    }
  }

  /// The terms of a's np pairs, per pair, with no reduction: vectorised.
  void terms(const Self<D>& s, Block& b, std::size_t np) const {
    const std::uint32_t* J = b.j.data();
    const double* RX[3] = {b.dx.data(), b.dy.data(), b.dz.data()};
    const double* R2 = b.r2.data();
    const Columns o(b);
#pragma omp simd
    for (std::size_t k = 0; k < np; ++k) {
      const Geometry<D> g = geometry(s, J[k], RX, R2[k], k);
      if constexpr (Cont) continuity(s, g, o, k);
      momentum(s, g, o, k);
    }
  }

  /// The sums of the columns, in list order.
  Sums<D> sum(const Self<D>& s, Block& b, std::size_t np) const {
    const Columns o(b);
    Sums<D> t;
    t.vs = s.cs;
    for (std::size_t k = 0; k < np; ++k) {
      for (int q = 0; q < D; ++q) {
        t.acc[q] -= o.T[q][k];
        if constexpr (V::kLaplacian) t.acc[q] += o.L[q][k];
      }
      t.vs = std::max(t.vs, o.VS[k]);
      if constexpr (Cont) {
        t.count += static_cast<int>(o.CN[k]);
        t.drho += o.DR[k];
        t.diff += o.DF[k];
      }
    }
    return t;
  }

  /// a's results from its sums: dv/dt, v_sig and the continuity rate.
  void finish(const Self<D>& s, const Sums<D>& t, const ContinuityOutput* cont) const {
    for (int k = 0; k < D; ++k) a[k][s.i] = t.acc[k];
    for (int k = D; k < 3; ++k) a[k][s.i] = 0.0;
    f.vsig[s.i] = t.vs;
    if constexpr (Cont) cont->store(s.i, s.rho, s.h, t.drho, t.diff, t.count);
  }
};

}  // namespace sph::standard_corrected
