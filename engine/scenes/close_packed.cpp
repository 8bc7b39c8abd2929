// Close-packed lattices (see close_packed.h).
#include "close_packed.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sph::scenes {
namespace {

std::size_t count_along(double length, double step, std::size_t multiple) {
  const auto n = static_cast<std::size_t>(std::llround(length / step));
  return std::max(multiple, (n + multiple - 1) / multiple * multiple);
}

}  // namespace

Lattice close_packed(int dim, const Vec3& lo, const Vec3& hi, double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("close_packed: spacing must be > 0");
  Lattice out;
  const double lx = hi.x - lo.x, ly = hi.y - lo.y, lz = hi.z - lo.z;
  if (dim == 1) {
    const std::size_t n = count_along(lx, spacing, 1);
    const double dx = lx / static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) out.x.push_back({lo.x + (i + 0.5) * dx, 0.0, 0.0});
    out.spacing = dx;
  } else if (dim == 2) {
    // Hexagonal: area per particle dx * dy with dy = dx sqrt(3)/2, so dx = s sqrt(2/sqrt(3)).
    const double dx0 = spacing * std::sqrt(2.0 / std::sqrt(3.0));
    const std::size_t nx = count_along(lx, dx0, 1), ny = count_along(ly, dx0 * std::sqrt(3.0) / 2.0, 2);
    const double dx = lx / static_cast<double>(nx), dy = ly / static_cast<double>(ny);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        out.x.push_back({lo.x + (i + 0.25 + 0.5 * static_cast<double>(j % 2)) * dx, lo.y + (j + 0.5) * dy, 0.0});
    out.spacing = std::sqrt(dx * dy);
  } else {
    // Body-centred cubic: two particles per cube of side a, a^3 / 2 = s^3.
    const double a0 = spacing * std::cbrt(2.0);
    const std::size_t nx = count_along(lx, a0, 1), ny = count_along(ly, a0, 1), nz = count_along(lz, a0, 1);
    const double ax = lx / static_cast<double>(nx), ay = ly / static_cast<double>(ny), az = lz / static_cast<double>(nz);
    for (std::size_t k = 0; k < nz; ++k)
      for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
          for (double c : {0.25, 0.75}) out.x.push_back({lo.x + (i + c) * ax, lo.y + (j + c) * ay, lo.z + (k + c) * az});
    out.spacing = std::cbrt(ax * ay * az / 2.0);
  }
  return out;
}

}  // namespace sph::scenes
