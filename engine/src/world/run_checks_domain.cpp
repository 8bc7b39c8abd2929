// The domain guard of RunChecks: in a scene with wall particles (a tank) the fluid stays inside the
// domain box, which holds the walls with a margin; a fluid particle found beyond the box along an open
// axis went through a wall or was flung far past the scene's extent, and the run near the walls is no
// longer what it claims. Warned (the run goes on; warnings.csv keeps the count of the steps that found
// it and the latest message), with how many particles and the first of them.
#include <cstdio>

#include "sph/run_checks.h"

namespace sph {

void RunChecks::check_domain(const Particles& p, const Domain& d, std::int64_t step, double t) {
  if (p.size() == p.fluid()) return;  // no walls: an open box only frames the view
  std::size_t out = 0, first = p.fluid();
  for (std::size_t i = 0; i < p.fluid(); ++i)
    for (int k = 0; k < p.dim(); ++k)
      if (d.bc[k] == Boundary::Open && (p.x[k][i] < d.lo[k] || p.x[k][i] > d.hi[k])) {
        if (out++ == 0) first = i;
        break;
      }
  if (out == 0) return;
  const auto id = static_cast<long long>(p.id[first]);
  char what[320];
  std::snprintf(what, sizeof what,
                "%zu fluid particles are outside the domain box (particle %lld at (%.3g, %.3g, %.3g)): they went "
                "through a wall or were flung far beyond the scene; results near the walls are not to be trusted "
                "(refine scene.dx or lower time.cfl)",
                out, id, p.x[0][first], p.x[1][first], p.x[2][first]);
  warn("domain", id, what, step, t, true);
}

}  // namespace sph
