// What the continuity equation writes per particle, and its neighbour statistics: shared by the
// continuity stage's own loop and the force loops that sum it in their pass (fuses_continuity).
#pragma once
#include "core/stage.h"

namespace sph {

struct ContinuityOutput {
  double* rate = nullptr;    ///< drho/dt
  double* nneigh = nullptr;  ///< neighbours within the support of h_a (self included)
  double delta_c0 = 0.0;     ///< 2 delta c0 of the density diffusion (times h_a)

  ContinuityOutput(Particles& p, const Params& prm)
      : rate(p[Field::DensityRate].data()), nneigh(p[Field::Neighbours].data()),
        delta_c0(2.0 * prm.density.diffusion * prm.liquid.c0) {}

  /// drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . grad W + 2 delta c0 h_a sum_b (diffusion terms).
  void store(std::size_t a, double rho_a, double h_a, double div_sum, double diff_sum, int count) const {
    rate[a] = rho_a * div_sum + delta_c0 * h_a * diff_sum;
    nneigh[a] = count;
  }
  /// The mean neighbour count, from the sum of the counts (exact: integers).
  static void finish(StageContext& c, double count_sum, std::size_t n) {
    c.stats.density = DensityStats{};
    c.stats.density.mean_neighbours = n ? count_sum / static_cast<double>(n) : 0.0;
  }
};

}  // namespace sph
