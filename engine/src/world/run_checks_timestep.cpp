// RunChecks' start check of a fixed timestep against the close passages of point masses: for every
// bound pair of a few point masses (h = 0, no softening), the osculating two-body orbit's pericentre
// and the leapfrog's energy error expected there (gravity/osculating_orbit.h), weighed by the pair's
// share of the scene's energy scale. A time.dt that would carry the run beyond the scene's energy
// bound is warned about before the first step, naming the pair, the pericentre and a time.dt that does.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gravity/osculating_orbit.h"
#include "sph/run_checks.h"
#include "sph/scene.h"

namespace sph {
namespace {

/// Point masses only: gravity, a fixed dt, an energy bound, no softening, a few bodies all with h = 0.
bool point_masses_at_fixed_dt(const RunConfig& cfg, const Particles& p) {
  const Params& prm = cfg.params;
  if (prm.physics.gravity == GravityType::None || !(prm.time.dt > 0.0) || !(cfg.scene->energy_bound > 0.0))
    return false;
  if (prm.gravity.eps > 0.0 || p.fluid() < 2 || p.fluid() > RunChecks::kFewBodies || !p.has(Field::H)) return false;
  for (std::size_t i = 0; i < p.fluid(); ++i)
    if (p[Field::H][i] != 0.0) return false;
  return true;
}

/// |E_kin| + |E_pot| of the point masses: the scale the energy check measures drift against.
double energy_scale(const Particles& p, double G) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    s += 0.5 * p[Field::Mass][i] * p.vel(i).norm2();
    for (std::size_t j = i + 1; j < p.fluid(); ++j)
      s += G * p[Field::Mass][i] * p[Field::Mass][j] / (p.pos(i) - p.pos(j)).norm();
  }
  return s;
}

/// The pair whose pericentre passage is expected to move the scene's energy most at the fixed dt.
struct WorstPair {
  std::size_t i = 0, j = 0;
  gravity::OsculatingOrbit orbit;
  double share = 0.0;  ///< |E| of the pair's orbit over the scene's energy scale
  double drift = 0.0;  ///< the expected energy error over the scene's energy scale
};

WorstPair worst_pair(const Particles& p, double G, double dt) {
  const double scale = energy_scale(p, G);
  WorstPair w;
  for (std::size_t i = 0; i < p.fluid(); ++i)
    for (std::size_t j = i + 1; j < p.fluid(); ++j) {
      const double mi = p[Field::Mass][i], mj = p[Field::Mass][j];
      if (!(mi > 0.0 && mj > 0.0)) continue;
      const gravity::OsculatingOrbit o = gravity::osculating_orbit(p.pos(j) - p.pos(i), p.vel(j) - p.vel(i), G * (mi + mj));
      if (!o.bound()) continue;
      const double share = mi * mj / (mi + mj) * std::abs(o.energy) / scale;
      const double drift = gravity::leapfrog_energy_error(o, dt) * share;
      if (drift > w.drift) w = {i, j, o, share, drift};
    }
  return w;
}

/// x rounded down to two significant digits (a timestep to recommend).
double floor2(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::floor(x / unit) * unit;
}

/// One of the scene's units (0 length, 2 time) as " AU", from its unit system's name "length, mass,
/// time" or "NAME (length, mass, time)"; empty when the name lists no three units (code units).
std::string unit(const UnitSystem& u, std::size_t which) {
  const std::size_t open = u.name.find('(');
  std::string names = open == std::string::npos ? u.name : u.name.substr(open + 1);
  if (!names.empty() && names.back() == ')') names.pop_back();
  std::vector<std::string> parts;
  for (std::size_t at = 0;;) {
    const std::size_t comma = names.find(", ", at);
    parts.push_back(names.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 2;
  }
  return parts.size() == 3 ? " " + parts[which] : "";
}

}  // namespace

void RunChecks::check_pericentres(const RunConfig& cfg, const Particles& p) {
  if (!point_masses_at_fixed_dt(cfg, p)) return;
  const double dt = cfg.params.time.dt, bound = cfg.scene->energy_bound;
  const WorstPair w = worst_pair(p, cfg.params.gravity.G, dt);
  if (!(w.drift > bound)) return;
  const auto a = static_cast<long long>(p.id[w.i]), b = static_cast<long long>(p.id[w.j]);
  const std::string len = unit(cfg.scene->units, 0), time = unit(cfg.scene->units, 2);
  char what[400];
  if (!(w.orbit.t_q > 0.0))
    std::snprintf(what, sizeof what,
                  "time.dt = %g cannot follow bodies %lld-%lld: they fall onto each other (pericentre q = 0); "
                  "use time.dt = 0 (adaptive)", dt, a, b);
  else
    std::snprintf(what, sizeof what,
                  "time.dt = %g is too large for the pericentre of bodies %lld-%lld (q = %.3g%s, passage time scale "
                  "t_q = %.2g%s, e = %.3g): |dE/E| ~ %.2g of their orbit expected, %.2g of the energy scale, beyond "
                  "this scene's bound %.2g; use time.dt <= %.2g or time.dt = 0 (adaptive)",
                  dt, a, b, w.orbit.q, len.c_str(), w.orbit.t_q, time.c_str(), w.orbit.e,
                  gravity::leapfrog_energy_error(w.orbit, dt), w.drift, bound,
                  floor2(gravity::leapfrog_dt_for(w.orbit, bound / w.share)));
  warn("timestep", a, what, 0, 0.0);
}

void RunChecks::check_levels(std::int64_t too_long, int levels, std::int64_t step, double t) {
  if (too_long <= 0) return;
  warn("timestep", -1,
       std::to_string(too_long) + " particle steps took the shortest of time.levels = " + std::to_string(levels) +
           " levels though they wanted less than half of it (the flow sped up inside a block): lower time.cfl",
       step, t);
}

}  // namespace sph
