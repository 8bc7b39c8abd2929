#include "io/export_box.h"

#include <algorithm>

namespace sph {

ExportBox export_box(const World& world) {
  ExportBox b;
  const Domain& d = world.domain();
  const Particles& p = world.particles();
  for (int k = 0; k < p.dim(); ++k) {
    if (d.bc[k] != Boundary::Open) {
      b.size[k] = d.length(k);
      b.shift[k] = -d.lo[k];
      b.periodic = true;
      if (d.bc[k] == Boundary::Wall) b.wall_axes.push_back(k);
      continue;
    }
    // open: four times the scene's domain (its view box, the same for the whole run) about its centre, so
    // the snapshots of a run share one frame; doubled while a particle lies outside [0, BoxSize)
    double lo = 0.0, hi = 0.0;
    if (p.size() > 0) {
      const auto [mn, mx] = std::minmax_element(p.x[k].begin(), p.x[k].begin() + static_cast<std::ptrdiff_t>(p.size()));
      lo = *mn;
      hi = *mx;
    }
    const double centre = 0.5 * (d.lo[k] + d.hi[k]);
    double size = d.length(k) > 0.0 ? 4.0 * d.length(k) : 1.0;
    for (int grow = 0; grow < 64 && (lo < centre - 0.5 * size || hi >= centre + 0.5 * size); ++grow) size *= 2.0;
    b.size[k] = size;
    b.shift[k] = 0.5 * size - centre;
  }
  return b;
}

}  // namespace sph
