// Seed 001 §7.1 (Monaghan 1994): a 2D water drop, initially the unit circle, with v0 = (-A0 x, A0 y),
// A0 = 100 /s, turns into an ellipse of semi-axes a and 1/a (reference: the incompressible ODE,
// reference/drop_ode.h). Tait EOS with gamma = 7, rho0 = 1000 kg/m^3 and the seed's k = 285.714 MN/m^2,
// which is the pressure constant B (c0 = sqrt(gamma B / rho0) = 1414.2 m/s; see sph/eos.h). Particles on
// a square lattice of spacing dx inside the circle (dx = 0.025: 5025 particles, PySPH's set), or 1308
// random points as in the seed (dart throwing with a minimum separation of 0.7 mean spacings, so no two
// points nearly coincide, which pure random points do). SI units.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/drop_reference.h"
#include "liquid_tank.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "sph/eos.h"

namespace sph::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> lattice_disc(double dx) {
  std::vector<Vec3> pts;
  const int n = static_cast<int>(std::ceil(1.0 / dx)) + 1;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const double x = i * dx, y = j * dx;
      if (x * x + y * y <= 1.0 + 1e-10) pts.push_back({x, y, 0.0});
    }
  return pts;
}

/// Random points in the unit disc, none closer than d_min (dart throwing, cell grid of size d_min).
std::vector<Vec3> random_disc(std::size_t count, std::uint64_t seed) {
  const double spacing = std::sqrt(kPi / static_cast<double>(count));
  const double d_min = 0.7 * spacing, d2 = d_min * d_min;
  const int cells = static_cast<int>(std::ceil(2.0 / d_min));
  std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(cells * cells));
  auto cell = [&](double v) { return std::clamp(static_cast<int>((v + 1.0) / d_min), 0, cells - 1); };
  std::vector<Vec3> pts;
  Random rng(seed);
  for (std::size_t tries = 0; pts.size() < count && tries < 1000 * count; ++tries) {
    const double x = 2.0 * rng.uniform() - 1.0, y = 2.0 * rng.uniform() - 1.0;
    if (x * x + y * y > 1.0) continue;
    const int cx = cell(x), cy = cell(y);
    bool ok = true;
    for (int gx = std::max(0, cx - 1); ok && gx <= std::min(cells - 1, cx + 1); ++gx)
      for (int gy = std::max(0, cy - 1); ok && gy <= std::min(cells - 1, cy + 1); ++gy)
        for (std::size_t k : grid[static_cast<std::size_t>(gx * cells + gy)]) {
          const double ddx = pts[k].x - x, ddy = pts[k].y - y;
          if (ddx * ddx + ddy * ddy < d2) { ok = false; break; }
        }
    if (!ok) continue;
    grid[static_cast<std::size_t>(cx * cells + cy)].push_back(pts.size());
    pts.push_back({x, y, 0.0});
  }
  return pts;
}

}  // namespace

SPH_SCENE(80, elliptical_drop_scene) {
  SceneSpec s = liquid_scene(
      "elliptical_drop",
      "seed 001 §7.1: water circle with v = (-100x, 100y) becomes an ellipse; ODE semi-axes as reference", {"none"});
  Params& d = s.defaults;
  d = liquid_params(std::sqrt(7.0 * 285.714e6 / 1000.0), 0.03);  // seed 001: k = 285.714 MN/m^2 is B
  set_run_times(d, 0.0076, 0.0004);
  s.params = {{"dx", 0.025, 0.002, 0.2, false, "lattice spacing [m] (with random = 0)", "m"},
              {"random", 0, 0, 1, true, "1: random points as in the seed (count of them), 0: square lattice", "dimensionless (0 or 1)"},
              {"count", 1308, 50, 1e6, true, "number of random points (seed 001: 1308)", "count"},
              {"seed", 1308, 0, 1e15, true, "random seed", "dimensionless (random seed)"},
              {"A0", 100.0, -1e4, 1e4, false, "initial velocity gradient, v = (-A0 x, A0 y) [1/s]", "1/s"},
              {"init_pressure", 1, 0, 1, true,
               "1: start with the pressure of the incompressible flow, P = rho0 A0^2 (1 - r^2)/2; 0: at P = 0", "dimensionless (0 or 1)"}};
  s.build = [s](const Params& prm, const SceneValues& v) {
    const bool random = v.at("random") != 0.0;
    const std::vector<Vec3> pts = random ? random_disc(static_cast<std::size_t>(v.at("count")),
                                                       static_cast<std::uint64_t>(v.at("seed")))
                                         : lattice_disc(v.at("dx"));
    const double area = random ? kPi / static_cast<double>(pts.size()) : v.at("dx") * v.at("dx");
    const double spacing = std::sqrt(area), rho0 = prm.liquid.rho0, A0 = v.at("A0");
    const double h = effective_eta(prm, 2) * spacing;
    Particles p = make_particles(prm, s.dim, pts.size());
    const bool pressurised = v.at("init_pressure") != 0.0;
    const double lattice = random ? 1.0 : lattice_density(prm, 2);  // DFSPH: the lattice's kernel sum is rho0
    for (std::size_t i = 0; i < pts.size(); ++i) {
      p.x[0][i] = pts[i].x;
      p.x[1][i] = pts[i].y;
      p.v[0][i] = -A0 * pts[i].x;
      p.v[1][i] = A0 * pts[i].y;
      // The incompressible flow accelerates as Dv/Dt = A0^2 (x, y) at t = 0 (dA/dt = 0 there), which
      // -grad P / rho provides with P = rho0 A0^2 (1 - r^2)/2, zero on the surface.
      const double r2 = pts[i].x * pts[i].x + pts[i].y * pts[i].y;
      const double P = pressurised ? 0.5 * rho0 * A0 * A0 * std::max(0.0, 1.0 - r2) : 0.0;
      const double rho = prm.physics.eos == EosType::Tait ? eos::tait_density(P + prm.liquid.p0, prm.liquid) : rho0;
      p[Field::Mass][i] = rho * area / lattice;
      if (p.has(Field::DfsphKappa)) p[Field::DfsphKappa][i] = P / rho0;  // DFSPH's warm start, P/rho
      p[Field::H][i] = h;
      if (p.has(Field::Density)) p[Field::Density][i] = rho;
    }
    SceneSetup out{std::move(p), {}, spacing, 0.0};
    out.domain.lo = {-1.3, -2.4, 0.0};  // a view box: the boundaries are open
    out.domain.hi = {1.3, 2.4, 1.0};
    return out;
  };
  s.reference = [](const Params&, const SceneValues& v) { return make_drop_reference(v.at("A0")); };
  s.error_bounds = {{"err_ab", 0.02}};  // measured to t = 0.0076: 0.013
  // the ODE is the incompressible drop's: the weakly compressible liquid follows it while the flow's
  // Mach number A0 R / c0 (R = 1 m) stays small (0.07 at the defaults)
  s.assumptions = {resolution("scene.dx", 0.002, 0.025),
                   {"A0 R / c0", 0.0, 0.1, "the ODE is that of an incompressible drop (Mach number <= 0.1)",
                    [](const Params& p, const SceneValues& v) { return std::abs(v.at("A0")) / p.liquid.c0; }}};
  return s;
}

}  // namespace sph::scenes
