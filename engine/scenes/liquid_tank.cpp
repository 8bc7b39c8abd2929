#include "liquid_tank.h"

#include <cmath>

#include "scene_util.h"
#include "sph/eos.h"
#include "sph/kernel.h"

namespace sph::scenes {

void add_fluid_block(LiquidLayout& out, double x0, double x1, double y0, double y1, double dx) {
  const auto nx = static_cast<long>(std::floor((x1 - x0) / dx + 1e-9));
  const auto ny = static_cast<long>(std::floor((y1 - y0) / dx + 1e-9));
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) out.fluid.push_back({x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dx, 0.0});
}

void add_wall_line(LiquidLayout& out, Vec3 a, Vec3 b, double ds) {
  const Vec3 d = b - a;
  const auto n = static_cast<long>(std::ceil(d.norm() / ds - 1e-9));
  for (long k = 0; k <= n; ++k) out.walls.push_back(a + d * (static_cast<double>(k) / static_cast<double>(n)));
}

void add_tank_walls(LiquidLayout& out, double L, double H, double dx, WallType type, int layers) {
  if (type == WallType::LennardJones) {
    const double o = 0.5 * dx, ds = 0.5 * dx;
    add_wall_line(out, {-o, H, 0}, {-o, -o, 0}, ds);          // left face, down to the corner
    add_wall_line(out, {-o + ds, -o, 0}, {L + o - ds, -o, 0}, ds);  // bottom, without the corners
    add_wall_line(out, {L + o, -o, 0}, {L + o, H, 0}, ds);      // right face, up from the corner
    return;
  }
  if (type != WallType::Dummy) return;
  const double T = layers * dx;  // wall thickness
  const auto nx = static_cast<long>(std::floor((L + 2 * T) / dx + 1e-9));
  const auto ny = static_cast<long>(std::floor((H + T) / dx + 1e-9));
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const double x = -T + (i + 0.5) * dx, y = -T + (j + 0.5) * dx;
      if (x > 0.0 && x < L && y > 0.0) continue;  // inside the tank
      out.walls.push_back({x, y, 0.0});
    }
}

int dummy_layers(const Params& prm, int dim) {
  const Kernel k(prm.kernel.type, dim);
  return static_cast<int>(std::ceil(k.support() * effective_eta(prm, dim) - 1e-9));
}

Particles make_liquid(const Params& prm, const LiquidLayout& layout, double dx, double surface, double g) {
  const std::size_t nf = layout.fluid.size(), nw = layout.walls.size();
  Particles p = make_particles(prm, 2, nf + nw);
  const LiquidParams& l = prm.liquid;
  const double h = effective_eta(prm, 2) * dx, area = dx * dx;
  const bool tait = prm.physics.eos == EosType::Tait;
  for (std::size_t k = 0; k < nf + nw; ++k) {
    const bool wall = k >= nf;
    const Vec3 x = wall ? layout.walls[k - nf] : layout.fluid[k];
    p.x[0][k] = x.x;
    p.x[1][k] = x.y;
    double rho = l.rho0;
    if (!wall && tait && g > 0.0) rho = eos::tait_density(l.rho0 * g * std::max(0.0, surface - x.y) + l.p0, l);
    p[Field::Mass][k] = rho * area;
    p[Field::H][k] = h;
    if (p.has(Field::Density)) p[Field::Density][k] = rho;
    p.kind[k] = static_cast<std::uint8_t>(wall ? Kind::Wall : Kind::Fluid);
  }
  return p;
}

}  // namespace sph::scenes
