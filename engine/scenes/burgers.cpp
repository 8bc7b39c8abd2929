// Burgers' equation by the finite pointset method (seed 002 §§3-4): the ramp u0 (eq. 6c) on
// [x_lo, x_hi] = [-0.5, 2.0] (the domain the seed's Table 1 implies: h_max = 2.5/(N - 1)), N equidistant
// points by default or the seed's random points (§3.2, Program 2: 3 per cell of width dx = 3 L / N).
// The MLS smoothing length is h = h_dx dx (seed: 1.5 dx), dx the point spacing (equidistant) or the
// cell width (random). Explicit Euler and the seed's CFL dt = dx / (2 max|u|) (time.cfl = 1).
//  - burgers_viscous: eps = 0.005 (eqs. 16-17); the seed shows t = 0.25, 0.75, 1.0 (Fig. 3);
//  - burgers_upwind: eps = 0, one-sided MLS (eqs. 18-21; Fig. 5).
// Points are kept on Gamma_0 by re-interpolation after every step (Note 3.2, fpm.control).
// Seed misprints: Table 1's h at N = 120 reads 0.0220 where its other rows give 2.5/(N - 1) = 0.0210 (the
// printed orders follow from 0.0210); Fig. 3's caption says "no viscosa" for the viscous run (eps = 0.005);
// §3.2 prints the cell index as (x - xmin)/m, Program 3 uses ceil((x - xmin)/dx).
#include <algorithm>
#include <cmath>

#include "reference/burgers_exact.h"
#include "reference/burgers_reference.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "sph/config.h"

namespace sph::scenes {
namespace {

SceneSpec burgers_base(FpmType type) {
  SceneSpec s;
  s.category = "finite pointset method (seed 002)";
  s.dim = 1;
  without_sph(s);
  s.defaults.physics.fpm = type;
  s.allow(Slot::Fpm, {"burgers_viscous", "burgers_upwind"});
  s.defaults.kernel.type = KernelType::M4;  // only the neighbour lists' reach (2 h) comes from the kernel
  s.defaults.time.integrator = IntegratorType::Euler;
  s.defaults.time.cfl = 1.0;
  set_run_times(s.defaults, 1.0, 0.25);
  s.defaults.fpm.eps = type == FpmType::BurgersViscous ? 0.005 : 0.0;
  s.convergence = {"scene.n", {60, 120, 240, 480, 960, 1920}, 0.8, ""};  // seed 002 Table 1
  s.params = {{"n", 300, 8, 1e6, true, "number of points N", "count"},
              {"a", 1.0, 0.01, 100.0, false, "ramp width a of u0 (seed 002 eq. 6c) [length]", "length"},
              {"x_lo", -0.5, -1e3, 1e3, false, "left end [length]", "length"},
              {"x_hi", 2.0, -1e3, 1e3, false, "right end [length]", "length"},
              {"h_dx", 1.5, 1.0, 6.0, false, "MLS smoothing length h in units of dx (seed 002: 1.5)", "dimensionless (multiple of dx)"},
              {"random", 0, 0, 1, true, "1: the seed's random points, 3 per cell (Program 2); 0: equidistant", "dimensionless (0 or 1)"},
              seed_param("random seed of the points")};
  s.build = [](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n"));
    const double lo = v.at("x_lo"), hi = v.at("x_hi"), a = v.at("a");
    if (!(hi > lo)) throw ConfigError("scene.x_hi must be greater than scene.x_lo");
    const bool random = v.at("random") != 0.0;
    Particles p = make_particles(prm, 1, n);
    std::vector<double> x(n);
    double h = 0.0;
    if (random) {  // Program 2: m cells of width dx, 3 random points each, sorted
      const std::size_t m = std::max<std::size_t>(n / 3, 3);
      const double dx = (hi - lo) / static_cast<double>(m);
      Random rng(static_cast<std::uint64_t>(v.at("seed")));
      for (std::size_t i = 0; i < n; ++i) x[i] = lo + (static_cast<double>(i % m) + rng.uniform()) * dx;
      std::sort(x.begin(), x.end());
      h = v.at("h_dx") * dx;
    } else {
      const double dx = (hi - lo) / static_cast<double>(n - 1);
      for (std::size_t i = 0; i < n; ++i) x[i] = lo + static_cast<double>(i) * dx;
      h = v.at("h_dx") * dx;
    }
    const double spacing = (hi - lo) / static_cast<double>(n - 1);
    for (std::size_t i = 0; i < n; ++i) {
      p.x[0][i] = x[i];
      p[Field::RestX][i] = x[i];
      p.v[0][i] = burgers_initial(x[i], a);
      p[Field::Mass][i] = spacing;  // sum m u^2 / 2 is the integral of u^2 / 2
      p[Field::H][i] = h;
    }
    SceneSetup out{std::move(p), {}, spacing, 0.0};
    out.domain.lo = {lo, 0, 0};
    out.domain.hi = {hi, 1, 1};
    out.domain.bc = {Boundary::Open, Boundary::Open, Boundary::Open};
    return out;
  };
  s.reference = [](const Params& prm, const SceneValues& v) {
    return make_burgers_reference(v.at("a"), prm.physics.fpm == FpmType::BurgersViscous ? prm.fpm.eps : 0.0);
  };
  // e(h) of eq. 22 measured at the defaults: viscous 0.032, upwind 0.010 (the bound: 1.5 x)
  s.error_bounds = {{"e_seed", type == FpmType::BurgersViscous ? 0.048 : 0.016}};
  s.assumptions = {{"scene.n / (x_hi - x_lo)", 120.0, 1e300,
                    "the error bound was measured at 120 points per length or more",
                    [](const Params&, const SceneValues& v) { return v.at("n") / (v.at("x_hi") - v.at("x_lo")); }}};
  return s;
}

}  // namespace

SPH_SCENE(200, burgers_viscous_scene) {
  SceneSpec s = burgers_base(FpmType::BurgersViscous);
  s.name = "burgers_viscous";
  s.description = "seed 002: viscous Burgers (eps = 0.005) by FPM from the ramp, 300 points, Euler; e(h) against eq. 22 "
                  "and the viscous solution";
  return s;
}

SPH_SCENE(210, burgers_upwind_scene) {
  SceneSpec s = burgers_base(FpmType::BurgersUpwind);
  s.name = "burgers_upwind";
  s.description = "seed 002: inviscid Burgers by FPM with one-sided (upwind) MLS, 300 points, Euler; e(h) against eq. 22";
  return s;
}

}  // namespace sph::scenes
