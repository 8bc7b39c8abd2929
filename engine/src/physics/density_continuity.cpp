// The continuity equation (seed 001 eqs. 39, 46, 49, 54): rho is evolved with
//   drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . grad_a W_ab,   V_b = m_b / rho_b,
// with grad_a W_ab = grad W(r_ab, h_a) for the standard formulation and the corrected gradient G_a(b)
// for the corrected ones, and v* the XSPH velocity when XSPH is on (eq. 46). The printed signs of eqs.
// 39 and 49 depend on the seed's notation for the gradient; this is drho/dt = -rho div v with the SPH
// divergence of the Lagrangian velocity. Fixed wall particles (v = 0) take part with dummy walls.
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "corrected_kernel.h"

namespace sph {
namespace {

class DensityContinuity final : public Stage {
 public:
  explicit DensityContinuity(const Physics& ph) : corrected_(ph.corrected()), xsph_(ph.xsph == Toggle::On) {}
  std::string_view name() const override { return "density: continuity"; }
  FieldSet needs() const override { return FieldSet{}.add(Field::Mass).add(Field::H); }
  FieldSet writes() const override { return FieldSet{}.add(Field::Neighbours); }
  std::vector<EvolvedPair> evolves() const override { return {{Field::Density, Field::DensityRate}}; }

  bool run(StageContext& c) override {
    const Kernel& K = c.kernel;
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    const auto& rho = p[Field::Density];
    const auto& h = p[Field::H];
    auto& rate = p[Field::DensityRate];
    auto& nneigh = p[Field::Neighbours];
    const bool skip_walls = !c.walls_in_sums();
    const std::vector<double>* dv[3] = {nullptr, nullptr, nullptr};
    if (xsph_)
      for (int k = 0; k < 3; ++k) dv[k] = &p[component(Field::XsphX, k)];
    std::unique_ptr<CorrectionFields> corr;
    if (corrected_) corr = std::make_unique<CorrectionFields>(p);
    const double support = K.support();
    double sum_nb = 0.0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : sum_nb) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      const double hi = h[i], R2 = support * support * hi * hi;
      double vi[3];
      for (int k = 0; k < 3; ++k) vi[k] = p.v[k][i] + (xsph_ ? (*dv[k])[i] : 0.0);
      double s = 0.0;
      int count = 1;  // itself
      for (std::uint32_t j : c.nl.of(i)) {
        if (j == i) continue;
        if (skip_walls && p.kind[j]) continue;
        double r[3];
        for (int k = 0; k < 3; ++k) r[k] = p.x[k][i] - p.x[k][j];
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (r2 >= R2 || r2 == 0.0) continue;
        ++count;
        const double rr = std::sqrt(r2), rinv = 1.0 / rr;
        double G[3];
        if (corrected_) {
          corr->gradient(i, r, K.W(rr, hi), K.dWdr(rr, hi), rinv, G);
        } else {
          const double dW = K.dWdr(rr, hi) * rinv;
          for (int k = 0; k < 3; ++k) G[k] = r[k] * dW;
        }
        double dot = 0.0;
        for (int k = 0; k < 3; ++k) {
          const double vj = p.v[k][j] + (xsph_ && !p.kind[j] ? (*dv[k])[j] : 0.0);
          dot += (vi[k] - vj) * G[k];
        }
        s += m[j] / rho[j] * dot;
      }
      rate[i] = rho[i] * s;
      nneigh[i] = count;
      sum_nb += count;
    }
    c.stats.density = DensityStats{};
    c.stats.density.mean_neighbours = n ? sum_nb / n : 0.0;
    return true;
  }

 private:
  bool corrected_, xsph_;
};

}  // namespace

std::unique_ptr<Stage> make_density_continuity(const Physics& ph, int) {
  return std::make_unique<DensityContinuity>(ph);
}

}  // namespace sph
