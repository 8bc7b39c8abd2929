// DFSPH's wall particles: the pressure of the fluid around each, as Adami et al.'s dummy particles
// (2012, JCP 231, 7057, eq. 27; see dfsph_solver.h). A wall particle beside a free surface takes the
// pressure of the water below it, not the zero of the surface particle next to it: with the surface
// particle's own (mirrored) kappa, its neighbours' pressure squeezed it into the wall unopposed (the
// tank's top corners, measured).
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "physics/dfsph_solver.h"

namespace sph {

void DfsphSolver::prepare_walls(const StageContext& c) {
  const Particles& p = c.p;
  const std::size_t nf = p.fluid(), real = p.size(), nw = real - nf;
  const auto& h = p[Field::H];
  const double support = c.kernel.support();
  const bool body = c.prm.physics.body_force == BodyForce::Uniform;
  const double g[3] = {body ? c.prm.body.gx : 0.0, body ? c.prm.body.gy : 0.0, body ? c.prm.body.gz : 0.0};
  auto weight = [&](std::size_t w, std::uint32_t f, double r[3]) {
    if (p.kind[f]) return 0.0;
    for (int k = 0; k < 3; ++k) r[k] = p.x[k][w] - p.x[k][f];
    const double d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    return d < support * h[w] ? c.kernel.W(d, h[w]) : 0.0;
  };
  wstart_.assign(nw + 1, 0);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t w = 0; w < nw; ++w) {
    std::size_t k = 0;
    double r[3];
    for (std::uint32_t f : c.nl.of(nf + w)) k += weight(nf + w, f, r) > 0.0 ? 1 : 0;
    wstart_[w + 1] = k;
  }
  for (std::size_t w = 0; w < nw; ++w) wstart_[w + 1] += wstart_[w];
  wsrc_.resize(wstart_[nw]);
  wweight_.resize(wstart_[nw]);
  whyd_.assign(nw, 0.0);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t w = 0; w < nw; ++w) {
    std::size_t k = wstart_[w];
    double sum = 0.0, hyd = 0.0, r[3];
    for (std::uint32_t f : c.nl.of(nf + w)) {
      const double W = weight(nf + w, f, r);
      if (W <= 0.0) continue;
      wsrc_[k] = f >= real ? p.ghost_src[f - real] : f;
      wweight_[k++] = W;
      sum += W;
      hyd += (g[0] * r[0] + g[1] * r[1] + g[2] * r[2]) * W;  // g . (x_w - x_f) W_wf
    }
    for (std::size_t q = wstart_[w]; q < k; ++q) wweight_[q] /= sum;
    whyd_[w] = k > wstart_[w] ? hyd / sum : 0.0;
  }
}

void DfsphSolver::wall_kappa(const std::vector<double>& k, bool hydrostatic, std::vector<double>& out) const {
  const std::size_t nw = whyd_.size();
  out.resize(nw);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t w = 0; w < nw; ++w) {
    double s = hydrostatic ? whyd_[w] : 0.0;
    for (std::size_t q = wstart_[w]; q < wstart_[w + 1]; ++q) s += wweight_[q] * k[wsrc_[q]];
    out[w] = wstart_[w + 1] > wstart_[w] ? std::max(0.0, s) : 0.0;
  }
}

}  // namespace sph
