// The N-body scenes of seed 003 ch. 2, in astronomical units: lengths in AU, masses in solar masses,
// times in years, G = 4 pi^2 AU^3 / (Msun yr^2). Point masses (h = 0), direct summation, leapfrog.
//  - two_body_fall: Sun and Earth released at rest 1 AU apart (§2.3), against eq. 2.17;
//  - kepler: the Earth at 1 AU with the seed's tangential v = 6.218 AU/yr (§2.4), or an orbit of any
//    eccentricity started at aphelion, against the Kepler orbit;
//  - solar_system: the seed's table of the Sun, eight planets and Pluto (§2.5.1), all on the x axis with
//    their tangential speeds along y; as in the seed the Sun starts at rest, so the system drifts with
//    the planets' momentum (0.0027 AU/yr).
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "nbody_common.h"
#include "reference/nbody_reference.h"
#include "scene_registration.h"
#include "scene_util.h"

namespace sph::scenes {
namespace {

constexpr double kG = 4.0 * std::numbers::pi * std::numbers::pi;  // AU^3 / (Msun yr^2)
constexpr double kEarth = 3.0e-6;                                  // seed 003 §2.3: m_T = 3.00e-6 Msun

std::vector<Body> fall_bodies(const SceneValues& v) {
  return {{1.0, {0, 0, 0}, {0, 0, 0}}, {v.at("m_earth"), {v.at("r0"), 0, 0}, {0, 0, 0}}};
}

std::vector<Body> kepler_bodies(const SceneValues& v) {
  const double r0 = v.at("r0"), e = v.at("e"), m = v.at("m_earth");
  // e < 0: the seed's speed; e >= 0: the speed at aphelion of an orbit of eccentricity e
  const double speed = e < 0.0 ? v.at("v0") : std::sqrt(kG * (1.0 + m) * (1.0 - e) / r0);
  return {{1.0, {0, 0, 0}, {0, 0, 0}}, {m, {r0, 0, 0}, {0, speed, 0}}};
}

/// Seed 003 table of §2.5.1: mass [Msun], mean distance [AU], tangential speed [AU/yr].
std::vector<Body> solar_bodies() {
  const double table[10][3] = {{1.0, 0.0, 0.0},          {1.660e-7, 0.387, 9.995},  {2.444e-6, 0.723, 7.313},
                               {3.003e-6, 1.0, 6.218},   {3.213e-7, 1.524, 5.036},  {9.547e-4, 5.203, 2.730},
                               {2.859e-4, 9.539, 2.013}, {4.367e-5, 19.182, 1.420}, {5.148e-5, 30.058, 1.134},
                               {6.483e-9, 39.440, 0.990}};
  std::vector<Body> b;
  for (const auto& row : table) b.push_back({row[0], {row[1], 0, 0}, {0, row[2], 0}});
  return b;
}

/// The point-mass scenes' common head: 2D, astronomical units, pure N-body with direct gravity (G in
/// AU^3 / (Msun yr^2)).
SceneSpec planet_scene(std::string name, std::string description) {
  SceneSpec s = scene_head(std::move(name), "gravity / N-body (seed 003 ch. 2)", std::move(description), 2,
                           UnitSystem::astronomical());
  make_nbody(s, GravityType::Direct, kG);
  return s;
}

/// The two-body references are point masses': no softening.
RefAssumption point_masses() {
  return {"gravity.eps", 0.0, 0.0, "the exact two-body motion is that of point masses (no softening)", {}};
}

}  // namespace

SPH_SCENE(120, two_body_fall_scene) {
  SceneSpec s = planet_scene(
      "two_body_fall",
      "seed 003 §2.3: the Earth released at rest 1 AU from the Sun falls in; against the closed form eq. 2.17");
  s.params = {{"r0", 1.0, 1e-3, 1e3, false, "initial separation [AU]", "AU"},
              {"m_earth", kEarth, 0.0, 1.0, false, "mass of the falling body [Msun] (seed: 3.00e-6)", "Msun"}};
  s.defaults.time.integrator = IntegratorType::RK4;  // the fall is not an orbit: accuracy, not symplecticity
  s.defaults.time.cfl = 0.01;                        // dt = 0.01 of the pair's dynamical time sqrt(r^3/mu)
  set_run_times(s.defaults, 0.175, 0.025);           // the encounter is at t = 0.1768 yr (r = 0.08 AU at 0.175)
  s.energy_bound = 1e-6;  // measured to t = 0.175: 5.8e-8 (RK4; the error grows towards the encounter)
  s.error_bounds = {{"err_r", 5e-9}};  // measured to t = 0.175: 3.4e-10
  s.assumptions = {point_masses()};
  s.build = [](const Params& prm, const SceneValues& v) { return bodies_setup(prm, 2, fall_bodies(v), 1.2 * v.at("r0")); };
  s.reference = [](const Params& prm, const SceneValues& v) { return make_fall_reference(fall_bodies(v), prm.gravity.G); };
  return s;
}

SPH_SCENE(130, kepler_scene) {
  SceneSpec s = planet_scene(
      "kepler",
      "seed 003 §2.4: Sun and Earth, v = 6.218 AU/yr (or any eccentricity); against the Kepler orbit");
  s.params = {{"r0", 1.0, 1e-3, 1e3, false, "initial separation (aphelion when e >= 0) [AU]", "AU"},
              {"v0", 6.218, 0.0, 1e3, false, "tangential speed of the Earth when e < 0 [AU/yr] (seed: 6.218)", "AU/yr"},
              {"e", -1.0, -1.0, 0.99, false, "eccentricity of an orbit started at aphelion; < 0: use v0", "dimensionless"},
              {"m_earth", kEarth, 0.0, 1.0, false, "mass of the orbiting body [Msun]", "Msun"}};
  s.defaults.time.dt = 0.002;  // fixed (leapfrog stays symplectic): 485 steps per orbit of the seed's 0.97 yr
  set_run_times(s.defaults, 10.0, 0.1);
  // measured to t = 10: 1.2e-6 (seed's orbit, e = 0.017); a drift within 3e-5 of the energy scale keeps
  // |dE/E| within 1e-4 at any eccentricity (|E| >= 1/3 of the scale |E_kin| + |E_pot|)
  s.energy_bound = 3e-5;
  // leapfrog keeps L to round-off (1.6e-14 measured); |dE/E| <= 1e-4 at any eccentricity (3.5e-6 measured)
  s.error_bounds = {{"dE", 1e-4}, {"dL", 1e-10}};
  s.assumptions = {point_masses()};
  s.build = [](const Params& prm, const SceneValues& v) { return bodies_setup(prm, 2, kepler_bodies(v), 1.3 * v.at("r0")); };
  s.reference = [](const Params& prm, const SceneValues& v) { return make_kepler_reference(kepler_bodies(v), prm.gravity.G); };
  // the energy error of ten years against the timestep (seed 003 eq. 2.24): sph bench kepler
  s.convergence = {"time.dt", {0.008, 0.004, 0.002, 0.001}, 10.0, "dE"};
  return s;
}

SPH_SCENE(140, solar_system_scene) {
  SceneSpec s = planet_scene(
      "solar_system",
      "seed 003 §2.5.1: the Sun, eight planets and Pluto from the seed's table; energy and angular momentum");
  s.defaults.time.dt = 0.001;  // fixed: 240 steps per orbit of Mercury (0.24 yr)
  set_run_times(s.defaults, 100.0, 1.0);
  s.energy_bound = 1e-6;  // measured to t = 100: 2.7e-8
  s.error_bounds = {{"dE", 1e-6}, {"dL", 1e-10}};  // measured to t = 100: 7.6e-8, 2.0e-14
  s.build = [](const Params& prm, const SceneValues&) { return bodies_setup(prm, 2, solar_bodies(), 42.0); };
  s.inset = {0.0, 0.0, 1.8, "inner planets"};  // Mars's aphelion 1.67 AU; the whole view is 84 AU wide
  s.reference = [](const Params& prm, const SceneValues&) {
    return make_conservation_reference(solar_bodies(), prm.gravity.G, prm.gravity.eps);
  };
  return s;
}

}  // namespace sph::scenes
