// XSPH (seed 001 eqs. 45-47; Monaghan 1989): particles move with v* = v + eps sum_b m_b (v_b - v_a)/rho_ab W_ab,
// a velocity smoothed over the fluid neighbours (walls excluded), which keeps the particles ordered.
// Seed misprint: eq. 45 writes v_ab = v_a - v_b (its eq. 43); with that sign XSPH would sharpen velocity
// differences instead of smoothing them. Monaghan's form, v_b - v_a, is used here.
// The correction v* - v is stored; the integrators drift with v + it and the continuity equation uses v*.
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class Xsph final : public Stage {
 public:
  Xsph()
      : Stage({.name = "XSPH",
               .needs = {Field::Mass, Field::Density, Field::H},
               .writes = {Field::XsphX, Field::XsphY, Field::XsphZ},
               .shares = {Field::XsphX, Field::XsphY, Field::XsphZ}}) {}
  bool run(StageContext& c) override {
    const Kernel& K = c.kernel;
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const int d = p.dim();
    const auto& m = p[Field::Mass];
    const auto& rho = p[Field::Density];
    const auto& h = p[Field::H];
    std::vector<double>* out[3] = {&p[Field::XsphX], &p[Field::XsphY], &p[Field::XsphZ]};
    const double eps = c.prm.xsph.eps;
    const double support = K.support();
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      double s[3] = {0.0, 0.0, 0.0};
      for (std::uint32_t j : c.nl.of(i)) {
        if (j == i || p.kind[j]) continue;
        const double dx = p.x[0][i] - p.x[0][j], dy = p.x[1][i] - p.x[1][j], dz = p.x[2][i] - p.x[2][j];
        const double r2 = dx * dx + dy * dy + dz * dz;
        const double hm = 0.5 * (h[i] + h[j]);
        if (r2 >= support * support * hm * hm) continue;
        const double wgt = m[j] / (0.5 * (rho[i] + rho[j])) * K.W(std::sqrt(r2), hm);
        for (int k = 0; k < d; ++k) s[k] += wgt * (p.v[k][j] - p.v[k][i]);
      }
      for (int k = 0; k < 3; ++k) (*out[k])[i] = eps * s[k];
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<Stage> make_xsph() { return std::make_unique<Xsph>(); }

}  // namespace sph
