#include "liquid_tank.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "reference/hydrostatic_reference.h"
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

double lattice_density(const Params& prm, int dim) {
  if (prm.physics.eos != EosType::Dfsph) return 1.0;
  const Kernel K(prm.kernel.type, dim);
  const double h = effective_eta(prm, dim), R = K.support() * h;  // in units of dx
  const int n = static_cast<int>(std::ceil(R));
  double sum = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = dim == 3 ? -n : 0; k <= (dim == 3 ? n : 0); ++k) {
        const double r = std::sqrt(static_cast<double>(i * i + j * j + k * k));
        if (r < R) sum += K.W(r, h);
      }
  return sum;
}

Particles make_liquid_3d(const Params& prm, const LiquidLayout& layout, Vec3 a, double surface) {
  const std::size_t nf = layout.fluid.size(), n = nf + layout.walls.size();
  Particles p = make_particles(prm, 3, n);
  const LiquidParams& l = prm.liquid;
  const double g = -prm.body.gz, vol = a.x * a.y * a.z;
  const double h = effective_eta(prm, 3) * (a.x == a.y && a.y == a.z ? a.x : std::cbrt(vol));  // a cubic lattice's dx exactly
  const double lattice = lattice_density(prm, 3);
  for (std::size_t k = 0; k < n; ++k) {
    const bool wall = k >= nf;
    const Vec3 x = wall ? layout.walls[k - nf] : layout.fluid[k];
    p.x[0][k] = x.x;
    p.x[1][k] = x.y;
    p.x[2][k] = x.z;
    const bool tait = prm.physics.eos == EosType::Tait;
    const double rho = wall || !tait ? l.rho0 : eos::tait_density(l.rho0 * g * std::max(0.0, surface - x.z) + l.p0, l);
    if (!wall && p.has(Field::DfsphKappa)) p[Field::DfsphKappa][k] = g * std::max(0.0, surface - x.z);  // P/rho0
    p[Field::Mass][k] = rho * vol / lattice;
    p[Field::H][k] = h;
    if (p.has(Field::Density)) p[Field::Density][k] = rho;
    p.kind[k] = static_cast<std::uint8_t>(wall ? Kind::Wall : Kind::Fluid);
  }
  return p;
}

Params liquid_params(double c0, double alpha) {
  Params d;
  d.physics.density = DensityMode::Continuity;
  d.physics.smoothing = HMode::Fixed;
  d.physics.eos = EosType::Tait;
  d.physics.force = ForceType::StandardCorrected;
  d.physics.viscosity = ViscType::Monaghan;
  d.physics.xsph = Toggle::Off;  // seed 001 §5.3: standard-corrected runs without XSPH
  d.physics.energy = Toggle::Off;
  d.physics.body_force = BodyForce::None;
  d.physics.walls = WallType::None;
  d.liquid.rho0 = 1000.0;
  d.liquid.gamma = 7.0;
  d.liquid.c0 = c0;
  // no tension: negative pressures at fronts and tips broke the corrected forms up (the dam break's
  // front reached -4.7e5 Pa and blew up at t = 0.35 s); water at a free surface is at P >= 0
  d.liquid.p_min = 0.0;
  // delta-SPH density diffusion: without it the corrected formulations break up by tensile instability
  // (elliptical drop at alpha = 0.03: t = 6.7 ms with h = 1.5 dx, 9.3 ms with h = 1.6 dx; at h = 1.3 dx
  // only alpha >= 0.1 survived, which holds its major axis 1.1% short at 7.6 ms)
  d.density.diffusion = 0.1;
  d.visc.alpha = alpha;  // seed 001: alpha ~ 0.01-0.1, beta = 0 for liquids
  d.visc.beta = 0.0;
  d.kernel.type = KernelType::M4;  // seed 001 eq. 14
  d.kernel.eta = 1.3;              // h = 1.3 dx, ~21 neighbours
  d.time.integrator = IntegratorType::PredictorCorrector;  // seed 001 eqs. 56-59
  d.time.cfl = 0.3;
  return d;
}

Params tank_params(double H, double alpha) {
  constexpr double g = kTankGravity;
  Params d = liquid_params(10.0 * std::sqrt(2.0 * g * H), alpha);
  d.physics.body_force = BodyForce::Uniform;
  d.physics.walls = WallType::Dummy;
  d.body.gx = 0.0;
  d.body.gy = -g;
  return d;
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
  const double lattice = lattice_density(prm, 2);
  for (std::size_t k = 0; k < nf + nw; ++k) {
    const bool wall = k >= nf;
    const Vec3 x = wall ? layout.walls[k - nf] : layout.fluid[k];
    p.x[0][k] = x.x;
    p.x[1][k] = x.y;
    double rho = l.rho0;
    if (!wall && tait && g > 0.0) rho = eos::tait_density(l.rho0 * g * std::max(0.0, surface - x.y) + l.p0, l);
    // DFSPH starts from the hydrostatic pressure as its warm start, kappa = P/rho0 = g depth
    if (!wall && p.has(Field::DfsphKappa)) p[Field::DfsphKappa][k] = g * std::max(0.0, surface - x.y);
    p[Field::Mass][k] = rho * area / lattice;
    p[Field::H][k] = h;
    if (p.has(Field::Density)) p[Field::Density][k] = rho;
    p.kind[k] = static_cast<std::uint8_t>(wall ? Kind::Wall : Kind::Fluid);
  }
  return p;
}

SceneSetup liquid_setup(const Params& prm, const LiquidLayout& layout, double dx, double surface) {
  return {make_liquid(prm, layout, dx, surface, -prm.body.gy), {}, dx, lj_strength(kTankGravity, surface)};
}

SceneSetup tank_setup(const Params& prm, double W, double H, double L, double top, double dx) {
  LiquidLayout lay;
  add_fluid_block(lay, 0.0, W, 0.0, H, dx);
  add_tank_walls(lay, L, top, dx, prm.physics.walls, dummy_layers(prm, 2));
  return liquid_setup(prm, lay, dx, H);
}

void hydrostatic_tank_head(SceneSpec& s, double size, double dx, double t_end, const char* width_help, int up) {
  s.params = {{"width", size, 0.01, 100.0, false, width_help, "m"},
              {"depth", size, 0.01, 100.0, false, "water depth H [m]", "m"},
              spacing_param(dx)};
  s.defaults = tank_params(size, 0.1);
  if (up == 2) std::swap(s.defaults.body.gy, s.defaults.body.gz);
  set_run_times(s.defaults, t_end, 0.1 * t_end);
  s.reference = [up](const Params& prm, const SceneValues& v) {
    const double g = -(up == 2 ? prm.body.gz : prm.body.gy);
    return make_hydrostatic_reference(v.at("depth"), v.at("width"), v.at("dx"), prm.liquid.rho0, g, up);
  };
}

SceneSpec liquid_scene(std::string name, std::string description, std::vector<std::string> walls) {
  SceneSpec s = scene_head(std::move(name), "free-surface liquids (seed 001)", std::move(description), 2, UnitSystem::si());
  s.allow(Slot::Eos, {"tait", "dfsph"});
  s.allow(Slot::Walls, std::move(walls));
  return s;
}

}  // namespace sph::scenes
