// The user's push (sph/push.h): a_push = w(r/R) (v_push - v) / tau on the fluid particles within R.
#include <cmath>

#include "core/parallel.h"
#include "sph/domain.h"
#include "sph/particles.h"
#include "sph/push.h"
#include "sph/world.h"

namespace sph {

double push_weight(double q) {
  if (!(q >= 0.0) || q >= 1.0) return 0.0;
  const double s = 1.0 - q * q;
  return s * s;
}

void add_push_acceleration(const Push& push, const Domain& d, Particles& p) {
  if (!push.active()) return;
  const int dim = p.dim();
  const std::size_t n = p.fluid();
  const double inv_r = 1.0 / push.radius, inv_tau = 1.0 / push.tau;
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    double r2 = 0.0;
    for (int k = 0; k < dim; ++k) {
      double dx = p.x[k][i] - push.x[k];
      if (d.bc[k] == Boundary::Periodic) {  // nearest image
        const double L = d.hi[k] - d.lo[k];
        dx -= L * std::nearbyint(dx / L);
      }
      r2 += dx * dx;
    }
    const double w = push_weight(std::sqrt(r2) * inv_r);
    if (w == 0.0) continue;
    for (int k = 0; k < dim; ++k) p.a[k][i] += w * (push.v[k] - p.v[k][i]) * inv_tau;
  }
}

void PushReplay::apply_due(World& w) {
  while (next_ < events_.size() && events_[next_].step <= w.steps()) w.set_push(events_[next_++].push);
}

}  // namespace sph
