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
    double lo = 0.0, hi = 0.0;
    if (p.size() > 0) {
      const auto [mn, mx] = std::minmax_element(p.x[k].begin(), p.x[k].begin() + static_cast<std::ptrdiff_t>(p.size()));
      lo = *mn;
      hi = *mx;
    }
    const double extent = hi - lo;
    b.size[k] = extent > 0.0 ? 4.0 * extent : 1.0;
    b.shift[k] = 0.5 * b.size[k] - 0.5 * (lo + hi);
  }
  return b;
}

}  // namespace sph
