// The continuity equation (seed 001 eqs. 39, 46, 49, 54): rho is evolved with
//   drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . grad_a W_ab,   V_b = m_b / rho_b,
// with grad_a W_ab = grad W(r_ab, h_a) for the standard formulation and the corrected gradient G_a(b)
// for the corrected ones, and v* the XSPH velocity when XSPH is on (eq. 46). The printed signs of eqs.
// 39 and 49 depend on the seed's notation for the gradient; this is drho/dt = -rho div v with the SPH
// divergence of the Lagrangian velocity. Fixed wall particles (v = 0) take part with dummy walls.
// With density.diffusion = delta > 0 the delta-SPH diffusion term (pair_terms.h) is added: without it the
// corrected formulations break up by tensile instability (the elliptical drop blew up at t = 6.7 ms with
// h = 1.5 dx and at 9.3 ms with h = 1.6 dx; with delta = 0.1 it runs stably past 10 ms).
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "continuity_output.h"
#include "corrected_kernel.h"
#include "pair_terms.h"
#include "sph/kernel_correction.h"

namespace sph {
namespace {

class DensityContinuity final : public Stage {
 public:
  explicit DensityContinuity(const Physics& ph)
      : Stage({.name = "density: continuity", .needs = {Field::Mass, Field::H}, .writes = {Field::Neighbours}}),
        corrected_(ph.corrected()), xsph_(ph.xsph == Toggle::On), fused_(fuses_continuity(ph)) {}
  std::vector<EvolvedPair> evolves() const override { return {{Field::Density, Field::DensityRate}}; }

  bool acts_after(const Params& prm, std::int64_t step) const override {
    return prm.density.reinit_every > 0 && step % prm.density.reinit_every == 0;
  }
  /// rho_a = sum_b V_b K*_1(x_a, x_b) rho_b = sum_b m_b K*_1: the density the particles' positions and
  /// masses imply, reconstructed to first order (exact for linear rho, so also at a free surface).
  void after_step(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    std::vector<double> fresh(n);
    const auto& rho = p[Field::Density];
    const bool skip_walls = !c.walls_in_sums();
#pragma omp parallel if (p.size() >= kParallelMin)
    {
      std::vector<double> w;
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
      for (std::size_t i = 0; i < n; ++i) {
        const auto nb = c.nl.of(i);
        corrected_kernel_weights(c.kernel, p, i, nb, 1, c.prm.correction.min_rcond, skip_walls, w);
        double s = 0.0;
        for (std::size_t k = 0; k < nb.size(); ++k) s += w[k] * rho[nb[k]];
        fresh[i] = s;
      }
    }
    std::copy(fresh.begin(), fresh.end(), p[Field::Density].begin());
  }

  bool run(StageContext& c) override {
    if (fused_) return true;  // the force loop summed the rate (fuses_continuity)
    const bool corr = corrected_ && c.p.has(Field::CorrXX);
    switch (c.p.dim()) {
      case 1: dispatch<1>(c, corr); break;
      case 2: dispatch<2>(c, corr); break;
      default: dispatch<3>(c, corr); break;
    }
    return true;
  }

 private:
  template <int D>
  void dispatch(StageContext& c, bool corr) {
    if (corr) xsph_ ? loop<D, true, true>(c) : loop<D, true, false>(c);
    else xsph_ ? loop<D, false, true>(c) : loop<D, false, false>(c);
  }

  template <int D, bool Corrected, bool Xsph>
  void loop(StageContext& c) {
    const Kernel& K = c.kernel;
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const double* m = p[Field::Mass].data();
    const double* rho = p[Field::Density].data();
    const double* h = p[Field::H].data();
    const ContinuityOutput out(p, c.prm);
    const std::uint8_t* kind = p.kind.data();
    const bool skip_walls = !c.walls_in_sums();
    const double* x[D];
    const double* v[D];
    const double* dv[D] = {};
    for (int k = 0; k < D; ++k) {
      x[k] = p.x[k].data();
      v[k] = p.v[k].data();
      if constexpr (Xsph) dv[k] = p[component(Field::XsphX, k)].data();
    }
    std::unique_ptr<CorrectionFields> corr;
    if constexpr (Corrected) corr = std::make_unique<CorrectionFields>(p);
    const double support = K.support();
    double sum_nb = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum_nb) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const double hi = h[i], R2 = support * support * hi * hi;
      const Kernel::Scale si = K.scale(hi);
      double diff = 0.0;
      double vi[D];
      for (int k = 0; k < D; ++k) vi[k] = v[k][i] + (Xsph ? dv[k][i] : 0.0);
      double s = 0.0;
      int count = 1;  // itself
      for (std::uint32_t j : c.nl.of(i)) {
        if (j == i) continue;
        if (skip_walls && kind[j]) continue;
        double r[D], r2 = 0.0;
        for (int k = 0; k < D; ++k) {
          r[k] = x[k][i] - x[k][j];
          r2 += r[k] * r[k];
        }
        if (r2 >= R2 || r2 == 0.0) continue;
        ++count;
        const double rr = std::sqrt(r2);
        double W, dW;
        K.eval(si, rr, W, dW);
        const double dW_r = dW / rr;
        double dot = 0.0;
        if constexpr (Corrected) {
          double G[D];
          corr->template gradient_d<D>(i, r, W, dW_r, G);
          for (int k = 0; k < D; ++k) dot += (vi[k] - v[k][j] - (Xsph && !kind[j] ? dv[k][j] : 0.0)) * G[k];
        } else {
          for (int k = 0; k < D; ++k) dot += (vi[k] - v[k][j] - (Xsph && !kind[j] ? dv[k][j] : 0.0)) * r[k];
          dot *= dW_r;
        }
        const double Vj = m[j] / rho[j];
        s += Vj * dot;
        diff += pair::density_diffusion(Vj, rho[i], rho[j], dW_r);
      }
      out.store(i, rho[i], hi, s, diff, count);
      sum_nb += count;
    }
    ContinuityOutput::finish(c, sum_nb, n);
  }

  bool corrected_, xsph_, fused_;
};

}  // namespace

std::unique_ptr<Stage> make_density_continuity(const Physics& ph, int) {
  return std::make_unique<DensityContinuity>(ph);
}

}  // namespace sph
