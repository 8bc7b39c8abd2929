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

Vec3 push_acceleration(const Push& push, const Domain& d, int dim, const Vec3& x, const Vec3& v) {
  const double xs[3] = {x.x, x.y, x.z}, vs[3] = {v.x, v.y, v.z};
  double r2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    double dx = xs[k] - push.x[k];
    if (d.bc[k] == Boundary::Periodic) {  // nearest image
      const double L = d.hi[k] - d.lo[k];
      dx -= L * std::nearbyint(dx / L);
    }
    r2 += dx * dx;
  }
  const double w = push.active() ? push_weight(std::sqrt(r2) / push.radius) : 0.0;
  double a[3] = {0.0, 0.0, 0.0};
  if (w != 0.0)
    for (int k = 0; k < dim; ++k) a[k] = w * (push.v[k] - vs[k]) / push.tau;
  return {a[0], a[1], a[2]};
}

void add_push_acceleration(const Push& push, const Domain& d, Particles& p) {
  if (!push.active()) return;
  const int dim = p.dim();
  const std::size_t n = p.fluid();
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = push_acceleration(push, d, dim, p.pos(i), p.vel(i));
    if (a.x == 0.0 && a.y == 0.0 && a.z == 0.0) continue;
    p.a[0][i] += a.x;
    if (dim > 1) p.a[1][i] += a.y;
    if (dim > 2) p.a[2][i] += a.z;
  }
}

void PushReplay::apply_due(World& w) {
  while (next_ < events_.size() && events_[next_].step <= w.steps()) w.set_push(events_[next_++].push);
}

}  // namespace sph
