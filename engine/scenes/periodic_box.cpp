// Seed 000 §4.1: gas in the periodic box [0,1]^2 (m = 0.1, v = 0, u = 0.05): a uniform lattice
// (§4.1.2), the lattice with one displaced particle (§4.1.3) and random particles (§4.1.4).
// Seed 000's equations (3.3.29) have no artificial viscosity, so these scenes turn it off.
// The lattice scenes also start from a hexagonal lattice (scene.lattice = 1) of the same density: which
// lattice stays at rest depends on the kernel (tests/scenes/lattice_stability_test.cpp: M4 and M5 keep
// the square one, M6, the Gaussian and the Wendland kernels the hexagonal one).
#include <cmath>

#include "close_packed.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "shared_setups.h"

namespace sph::scenes {
namespace {

SceneSpec box_base() {
  SceneSpec s;
  s.category = "gas dynamics / periodic box (seed 000 §4.1)";
  s.dim = 2;
  s.defaults.physics.viscosity = ViscType::None;
  set_run_times(s.defaults, 30.0, 1.0);
  s.allow(Slot::Eos, {"ideal_gas", "isothermal"});
  s.allow(Slot::Walls, {"none"});
  s.energy_bound = 5e-3;  // measured to t = 30: box_random 2.0e-3, box_perturbed 2.3e-4 (leapfrog)
  return s;
}

SceneSetup periodic_domain(Particles p, double spacing) {
  return {std::move(p), periodic_box(2, {0, 0, 0}, {1, 1, 1}), spacing, 0.0};
}

/// Hexagonal rows of n particles spacing dx = 1/n, an even number of rows dy = dx sqrt(3)/2 apart, in the
/// periodic box [0, 1] x [0, rows dy] (its height is the nearest that the rows tile); the masses give
/// the square lattice's density mass n^2; u = u0; h guess from the lattice density.
SceneSetup hexagonal_lattice(const SceneSpec& spec, const Params& prm, const SceneValues& v) {
  const auto n = static_cast<std::size_t>(v.at("n_side"));
  const double dx = 1.0 / static_cast<double>(n), dy = dx * std::sqrt(3.0) / 2.0;
  const std::size_t rows = 2 * static_cast<std::size_t>(std::llround(0.5 / dy));
  const double height = static_cast<double>(rows) * dy;
  const Lattice l = close_packed(2, {0, 0, 0}, {1.0, height, 1.0}, std::sqrt(dx * dy));
  const double m = v.at("mass") * dx * dy * static_cast<double>(n * n);
  Particles p = gas_particles(prm, spec.dim, l.x, m, effective_eta(prm, 2) * l.spacing, v.at("u0"));
  return {std::move(p), periodic_box(2, {0, 0, 0}, {1.0, height, 1.0}), l.spacing, 0.0};
}

/// The lattice of scene.lattice: 0 n x n at the cell centres of the unit box (seed 000), mass m, u = u0,
/// h guess from the lattice density; 1 the hexagonal one above.
SceneSetup lattice(const SceneSpec& spec, const Params& prm, const SceneValues& v) {
  if (v.at("lattice") != 0.0) return hexagonal_lattice(spec, prm, v);
  const auto n = static_cast<std::size_t>(v.at("n_side"));
  const double dx = 1.0 / static_cast<double>(n), eta = effective_eta(prm, 2);
  std::vector<Vec3> x;
  x.reserve(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) x.push_back({(i + 0.5) * dx, (j + 0.5) * dx, 0.0});
  return periodic_domain(gas_particles(prm, spec.dim, x, v.at("mass"), eta * dx, v.at("u0")), dx);
}

std::vector<SceneParam> lattice_params(double n_side) {
  return {{"n_side", n_side, 2, 2000, true, "particles per side of the lattice", "count"},
          {"mass", 0.1, 1e-12, 1e12, false, "particle mass (seed 000: 0.1)", "mass"},
          {"u0", 0.05, 1e-12, 1e12, false, "initial specific internal energy (seed 000: 0.05)", "energy/mass"},
          {"lattice", 0, 0, 1, true,
           "0: square lattice n_side x n_side (seed 000); 1: hexagonal, rows of n_side, the box's height rounded to an "
           "even number of rows, the same density (mass is then the square lattice's particle mass)",
           "dimensionless (0 square, 1 hexagonal)"}};
}

}  // namespace

SPH_SCENE(40, box_lattice_scene) {
  SceneSpec s = box_base();
  s.name = "box_lattice";
  s.description = "seed 000 §4.1.2: 10x10 lattice at rest in a periodic box; stays at rest (|v| ~ round-off)";
  s.params = lattice_params(10);
  s.build = [s](const Params& p, const SceneValues& v) { return lattice(s, p, v); };
  return s;
}

SPH_SCENE(50, box_perturbed_scene) {
  SceneSpec s = box_base();
  s.name = "box_perturbed";
  s.description = "seed 000 §4.1.3: the lattice with one particle displaced; disorder spreads (t ~ 12)";
  s.params = lattice_params(10);
  s.params.push_back({"shift", 0.2, -0.49, 0.49, false, "displacement of the centre particle, in lattice spacings", "lattice spacings"});
  s.build = [s](const Params& p, const SceneValues& v) {
    SceneSetup out = lattice(s, p, v);
    const auto n = static_cast<std::size_t>(v.at("n_side"));
    const std::size_t k = (n / 2) * n + n / 2;
    out.particles.x[0][k] += v.at("shift") / static_cast<double>(n);
    out.particles.x[1][k] += 0.5 * v.at("shift") / static_cast<double>(n);
    return out;
  };
  return s;
}

SPH_SCENE(60, box_random_scene) {
  SceneSpec s = box_base();
  s.name = "box_random";
  s.description = "seed 000 §4.1.4: 500 random particles in a periodic box, quintic kernel; relaxes";
  s.defaults.kernel.type = KernelType::M6;
  s.params = {{"count", 500, 2, 1e7, true, "number of particles", "count"},
              {"mass", 0.1, 1e-12, 1e12, false, "particle mass", "mass"},
              {"u0", 0.05, 1e-12, 1e12, false, "initial specific internal energy", "energy/mass"},
              {"seed", 2017, 0, 1e15, true, "random seed (same seed, same particles on every platform)", "dimensionless (random seed)"}};
  s.build = [s](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("count"));
    Random rng(static_cast<std::uint64_t>(v.at("seed")));
    const double h = effective_eta(prm, 2) / std::sqrt(static_cast<double>(n));
    std::vector<Vec3> x(n);
    for (Vec3& r : x) {
      r.x = rng.uniform();  // x before y: the random sequence of every platform
      r.y = rng.uniform();
    }
    return periodic_domain(gas_particles(prm, s.dim, x, v.at("mass"), h, v.at("u0")),
                           1.0 / std::sqrt(static_cast<double>(n)));
  };
  return s;
}

}  // namespace sph::scenes
