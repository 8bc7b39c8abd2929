// Spheres of seed 003 with G = M = R = 1 and the density profile rho = M / (2 pi R^2 r) (eq. 2.42),
// sampled by rejection as in §2.6: r uniform in [0, R] kept with probability r/R (the radial density
// 4 pi r^2 rho is proportional to r), directions uniform on the sphere.
//  - dust_sphere: pressureless collapse with Plummer softening (§2.7; N = 4000, eps = 0.1, Fig. 2.17);
//  - dust_collision: two such spheres (§3.4.2). The seed places them 10 apart at rest (N = 1000 each),
//    where they need t ~ 25 to meet; here they start 4 apart approaching at 0.5 each, so they collide
//    within t = 3 (scene.separation = 10, scene.speed = 0 give the seed's set-up);
//  - evrard: the adiabatic collapse of a cold gas sphere (Evrard 1988; §3.4.1): u = 0.05 G M / R,
//    gamma = 5/3, alpha = 1, beta = 2, eps = 0.05, N = 4096, SPH with self-gravity.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "nbody_common.h"
#include "scene_registration.h"
#include "scene_util.h"
#include "shared_setups.h"

namespace sph::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

/// n points of the rho ~ 1/r sphere of radius R (seed 003 §2.6), deterministic for a seed.
std::vector<Vec3> sample_sphere(std::size_t n, double R, std::uint64_t seed) {
  Random rng(seed);
  std::vector<Vec3> pts;
  pts.reserve(n);
  while (pts.size() < n) {
    const double r = R * rng.uniform();
    if (rng.uniform() * R > r) continue;  // rejection: accepted with probability r/R
    const double mu = 2.0 * rng.uniform() - 1.0, phi = 2.0 * kPi * rng.uniform();
    const double s = std::sqrt(1.0 - mu * mu);
    pts.push_back({r * s * std::cos(phi), r * s * std::sin(phi), r * mu});
  }
  return pts;
}

/// The dust scenes' start (§2.7, §3.4.2): pure N-body with tree gravity, Plummer softening eps = 0.1
/// (Fig. 2.17) and the time-step factor cfl, to t = 3 with an output every 0.1.
SceneSpec dust_base(std::string name, std::string description, double cfl) {
  SceneSpec s = sphere_head(std::move(name), std::move(description));
  set_run_times(s.defaults, 3.0, 0.1);
  make_nbody(s, GravityType::Tree, 1.0);
  s.defaults.gravity.eps = 0.1;
  s.defaults.time.cfl = cfl;
  return s;
}

/// Appends n dust particles of total mass M: a sample_sphere of radius 1 (its `seed`) moved to `centre`,
/// every particle at velocity v.
void add_dust_sphere(std::vector<Body>& b, std::size_t n, std::uint64_t seed, double M, Vec3 centre, Vec3 v) {
  for (const Vec3& x : sample_sphere(n, 1.0, seed)) b.push_back({M / static_cast<double>(n), x + centre, v});
}

/// The seed of the rejection sampling (sample_sphere), a parameter of every scene here.
SceneParam sampling_seed_param() { return seed_param("random seed of the rejection sampling"); }

}  // namespace

SPH_SCENE(150, dust_sphere_scene) {
  // cfl: dt = 0.05 sqrt(eps / |a|) keeps |dE/E| < 1e-4 (0.2: 4e-3)
  SceneSpec s = dust_base(
      "dust_sphere",
      "seed 003 §2.7: a pressureless sphere rho ~ 1/r collapses under its own gravity (N = 4000, eps = 0.1)", 0.05);
  s.params = {{"n", 4000, 2, 1e7, true, "number of particles", "count"},
              sampling_seed_param()};
  s.build = [](const Params& prm, const SceneValues& v) {
    std::vector<Body> b;
    add_dust_sphere(b, static_cast<std::size_t>(v.at("n")), static_cast<std::uint64_t>(v.at("seed")), 1.0, {}, {});
    return bodies_setup(prm, 3, b, 1.2);
  };
  s.energy_bound = 2e-3;  // measured to t = 3: 3.3e-4 (the tree's force error through the collapse)
  return s;
}

SPH_SCENE(160, dust_collision_scene) {
  SceneSpec s = dust_base(
      "dust_collision",
      "seed 003 §3.4.2: two rho ~ 1/r dust spheres meet head-on (4 apart, approaching at 0.5 each)", 0.2);
  s.params = {{"n", 1000, 2, 1e7, true, "particles per sphere (seed: 1000)", "count"},
              {"separation", 4.0, 0.0, 1e3, false, "distance between the centres (seed: 10)", "length"},
              {"speed", 0.5, 0.0, 1e3, false, "speed of each sphere towards the other (seed: 0)", "length/time"},
              sampling_seed_param()};
  s.build = [](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n"));
    const double d = v.at("separation"), u = v.at("speed");
    const auto seed = static_cast<std::uint64_t>(v.at("seed"));
    std::vector<Body> b;
    add_dust_sphere(b, n, seed, 0.5, {-0.5 * d, 0, 0}, {u, 0, 0});
    add_dust_sphere(b, n, seed + 1, 0.5, {0.5 * d, 0, 0}, {-u, 0, 0});
    return bodies_setup(prm, 3, b, 0.5 * d + 1.5);
  };
  s.energy_bound = 2e-2;  // measured to t = 3: 3.4e-3 (the collision at cfl 0.2, the tree's force error)
  return s;
}

SPH_SCENE(170, evrard_scene) {
  SceneSpec s = gas_sphere_base(
      "evrard",
      "seed 003 §3.4.1 (Evrard 1988): a cold gas sphere rho ~ 1/r collapses, bounces and heats (N = 4096)");
  s.params = {{"n", 4096, 8, 1e7, true, "number of particles (seed: 4096)", "count"},
              {"u0", 0.05, 0.0, 10.0, false, "initial specific internal energy [G M / R] (seed: 0.05)", "G M / R"},
              sampling_seed_param()};
  Params& d = s.defaults;
  d.gravity.eps = 0.05;  // seed 003 §3.4.1
  // The fast multipole method: to t = 3 on two threads 17.6 s against the tree's 28.1 s, |dE/E| 3.9e-4
  // against 4.3e-4 (seed 1); physics.gravity = tree stays available (and its GUI overlay). Without the
  // relative guard, at theta = 0.7: 1.49x less wall time, max |dE/E| 3.0e-4, 3.5e-4, 3.3e-4 for seeds
  // 1, 2, 3 (the guard's 3.9e-4, 4.2e-4, 4.0e-4), RMS force error 8.7e-4 instead of 1.2e-4 (N = 4096,
  // gravity_fmm_bench --sphere r1). The energy error is the leapfrog's at time.cfl = 0.3 (cfl 0.1:
  // 1.1e-4, the force error's floor; theta 0.8: 2.5e-4, 0.6: 3.4e-5).
  d.physics.gravity = GravityType::Fmm;
  d.gravity.fmm_theta = 0.7;
  d.gravity.fmm_tol = 0.0;
  s.energy_bound = 2e-3;  // measured to t = 3: 3.0e-4, the leapfrog error at the bounce (time.cfl / 2: / 3.0)
  d.gas.gamma = 5.0 / 3.0;
  set_run_times(d, 3.0, 0.1);
  s.allow(Slot::Eos, {"ideal_gas"});
  s.build = [](const Params& prm, const SceneValues& v) {
    const auto n = static_cast<std::size_t>(v.at("n"));
    const std::vector<Vec3> pts = sample_sphere(n, 1.0, static_cast<std::uint64_t>(v.at("seed")));
    Particles p = make_particles(prm, 3, n);
    const double m = 1.0 / static_cast<double>(n), eta = effective_eta(prm, 3);
    for (std::size_t i = 0; i < n; ++i) {
      p.x[0][i] = pts[i].x; p.x[1][i] = pts[i].y; p.x[2][i] = pts[i].z;
      p[Field::Mass][i] = m;
      const double rho = 1.0 / (2.0 * kPi * std::max(pts[i].norm(), 0.01));  // eq. 2.42: the first h guess
      p[Field::H][i] = eta * std::cbrt(m / rho);
      if (p.has(Field::Energy)) p[Field::Energy][i] = v.at("u0");
    }
    SceneSetup out{std::move(p), {}, sphere_spacing(n, 1.0), 0.0};
    out.domain.lo = {-1.5, -1.5, -1.5};
    out.domain.hi = {1.5, 1.5, 1.5};
    return out;
  };
  return s;
}

}  // namespace sph::scenes
