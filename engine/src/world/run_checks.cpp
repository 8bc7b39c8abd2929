// RunChecks: the checks after each step that keep a run from going bad silently: non-finite state
// (stop), a collapsing timestep or a finite blow-up of the energy (stop), particles escaping through
// walls (stop) or crossing them (warn), energy drift beyond the scene's bound (warn), an h solve that
// did not converge (warn). The start check of a fixed timestep against pericentre passages is in
// run_checks_timestep.cpp, the reference guard in run_checks_reference.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/parallel.h"
#include "sph/run_checks.h"

namespace sph {

void RunChecks::tally(const WallCrossings& w) {
  crossings_.reflected += w.reflected;
  crossings_.escaped += w.escaped;
  crossings_.first_reflected = std::min(crossings_.first_reflected, w.first_reflected);
  crossings_.first_escaped = std::min(crossings_.first_escaped, w.first_escaped);
}

void RunChecks::warn(const std::string& kind, std::int64_t particle, const std::string& message, std::int64_t step,
                     double t, bool latest) {
  for (RunWarning& w : warnings_)
    if (w.kind == kind) {
      ++w.times;
      if (latest) w.message = message;
      return;
    }
  warnings_.push_back({kind, message, step, t, particle, 1});
}

std::int64_t RunChecks::fastest_particle(const Particles& p) {
  const std::size_t n = p.fluid();
  double best = -1.0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {  // serial: the first of equal maxima, NaN counted as largest
    const double a = p.a[0][i] * p.a[0][i] + p.a[1][i] * p.a[1][i] + p.a[2][i] * p.a[2][i];
    if (std::isnan(a)) return p.id[i];
    if (a > best) { best = a; k = i; }
  }
  return n ? static_cast<std::int64_t>(p.id[k]) : -1;
}

void RunChecks::check_finite(const Particles& p, std::int64_t step, double t) {
  // Finite and within single precision: snapshots, the display and the float outputs hold the state as
  // floats, so a value beyond FLT_MAX (a Tait pressure of 1e40 Pa after a wild timestep, say) would show
  // as inf in a run that had not stopped.
  constexpr double kLargest = std::numeric_limits<float>::max();
  auto bad = [&](const std::vector<double>& a, std::size_t n, const char* name) {
    std::size_t first = n;  // lowest index of a non-finite value: the same for any thread count
#pragma omp parallel for reduction(min : first) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i)
      if (!(std::abs(a[i]) <= kLargest)) first = std::min(first, i);
    if (first == n) return;
    if (!std::isfinite(a[first])) throw DivergedError(p.id[first], step, t, name);
    char what[200];
    std::snprintf(what, sizeof what, "particle %lld has %s = %.3g, beyond single precision (|value| > %.3g)",
                  static_cast<long long>(p.id[first]), name, a[first], kLargest);
    throw DivergedError(p.id[first], step, t, name, what);
  };
  const char* xn[3] = {"x", "y", "z"};
  const char* vn[3] = {"vx", "vy", "vz"};
  for (int k = 0; k < p.dim(); ++k) { bad(p.x[k], p.fluid(), xn[k]); bad(p.v[k], p.fluid(), vn[k]); }
  // the sound speed too: a negative internal energy (an explicit step that overshoots a fast cooling)
  // leaves P finite but c = sqrt(gamma P/rho) NaN, which the display and the outputs would show
  for (Field f : {Field::Density, Field::H, Field::Energy, Field::Pressure, Field::SoundSpeed})
    if (p.has(f)) bad(p[f], p.size(), std::string(info(f).key).c_str());
}

void RunChecks::check_dt(double dt, double dt_free, bool adaptive, const Particles& p, std::int64_t step, double t) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    const std::int64_t id = fastest_particle(p);
    throw DivergedError(id, step, t, "dt",
                        "no finite timestep (particle " + std::to_string(id) + " has the largest acceleration)");
  }
  // A blow-up that stays finite (velocities of 1e10, E_kin of 1e21) shows as a collapsing adaptive dt:
  // the run would crawl forever. A millionth of the first step's dt is far below any physical change.
  if (!adaptive) return;
  if (dt_first_ <= 0.0) dt_first_ = dt_free;
  if (dt_free < 1e-6 * dt_first_) {
    const std::int64_t id = fastest_particle(p);
    char what[220];
    std::snprintf(what, sizeof what,
                  "the timestep collapsed to %.3g (the first step took %.3g; particle %lld has the largest "
                  "acceleration): the run is unstable",
                  dt_free, dt_first_, static_cast<long long>(id));
    throw DivergedError(id, step, t, "dt", what);
  }
}

void RunChecks::check_walls(const Particles& p, const Params& prm, std::int64_t step, double t) {
  const WallCrossings w = crossings_;
  crossings_ = WallCrossings{};
  char what[240];
  if (w.escaped > 0) {
    const auto id = static_cast<long long>(p.id[w.first_escaped]);
    std::snprintf(what, sizeof what,
                  "particle %lld went through a wall and out of the domain (%zu particles in all): the timestep is "
                  "far too long (time.cfl = %g, time.dt = %g)",
                  id, w.escaped, prm.time.cfl, prm.time.dt);
    throw DivergedError(id, step, t, "x", what);
  }
  if (w.reflected > 0) {
    const auto id = static_cast<long long>(p.id[w.first_reflected]);
    std::snprintf(what, sizeof what,
                  "particle %lld crossed a wall and was reflected back (the mirror particles should have stopped it): "
                  "lower time.cfl (now %g)",
                  id, prm.time.cfl);
    warn("wall", id, what, step, t);
  }
}

void RunChecks::check_h_solve(const DensityStats& d, std::int64_t step, double t) {
  if (d.not_converged == 0) return;
  char what[240];
  std::snprintf(what, sizeof what,
                "the smoothing-length solve did not converge for %zu particles (the first is particle %lld): their "
                "density is approximate; raise h.max_iter or change kernel.eta",
                d.not_converged, static_cast<long long>(d.first_not_converged));
  warn("h_solve", d.first_not_converged, what, step, t);
}

void RunChecks::check_projection(const ProjectionStats& s, const LiquidParams& l, std::int64_t step, double t) {
  if (s.density_iterations < l.dfsph_max_iter && s.divergence_iterations < l.dfsph_max_iter) return;
  char what[240];
  std::snprintf(what, sizeof what,
                "a DFSPH pressure solve stopped at liquid.dfsph_max_iter = %d iterations with the mean density error "
                "at %.3g (liquid.dfsph_eta = %.3g): the liquid is compressed; raise the cap or lower time.cfl",
                l.dfsph_max_iter, s.density_error, l.dfsph_eta);
  warn("dfsph", -1, what, step, t);
}

void RunChecks::check_energy(const RunConfig& cfg, const std::function<Diagnostics()>& diagnostics, const Particles& p,
                             std::int64_t step, double t, bool now) {
  // Every stage conserves or dissipates E_kin + E_int + E_pot (the corrected forms to truncation error),
  // so a total energy that grows by many times its initial scale is a blow-up that has not (yet) reached
  // inf or NaN. A scene that conserves energy is checked every step against its bound (a pass over the
  // particles), and so are a few point masses summed directly (a pericentre passage may take a step or
  // two); the others, and those with gravity (whose potential may need a tree walk of its own), every 16
  // steps and at each output (`now`).
  const double bound = cfg.scene->energy_bound;
  const GravityType gravity = cfg.params.physics.gravity;
  const bool few_bodies = gravity == GravityType::Direct && p.fluid() <= kFewBodies;
  const bool every_step = bound > 0.0 && (gravity == GravityType::None || few_bodies);
  const bool due = step % 16 == 0 || every_step;
  if (now ? due : !due && energy_scale_ >= 0.0) return;  // `now` after check_step: only what it skipped
  const Diagnostics d = diagnostics();
  if (energy_scale_ < 0.0) {
    energy_scale_ = std::abs(d.E_kin) + std::abs(d.E_int) + std::abs(d.E_pot);
    energy0_ = d.E_tot;
    return;
  }
  if (!(energy_scale_ > 0.0)) return;
  const double drift = (d.E_tot - energy0_) / energy_scale_;
  const double fail = bound > 0.0 ? std::min(0.1, 100.0 * bound) : 10.0;
  char what[320];
  if (drift > fail) {
    const std::int64_t id = fastest_particle(p);
    std::snprintf(what, sizeof what,
                  "the total energy grew from %.4g to %.4g (by %.3g of its initial scale; E_kin = %.3g, v_max = %.3g; "
                  "particle %lld has the largest acceleration): the run is unstable",
                  energy0_, d.E_tot, drift, d.E_kin, d.v_max, static_cast<long long>(id));
    throw DivergedError(id, step, t, "E_tot", what);
  }
  if (bound > 0.0 && std::abs(drift) > bound && std::abs(drift) >= worst_drift_) {
    worst_drift_ = std::abs(drift);
    const bool euler = cfg.params.time.integrator == IntegratorType::Euler;
    const bool fixed = gravity != GravityType::None && cfg.params.time.dt > 0.0;
    std::snprintf(what, sizeof what,
                  "E_tot drifted by %.2g of its initial scale, beyond this scene's bound %.2g: %s", drift, bound,
                  euler   ? "forward Euler is unstable for this problem (time.integrator: use leapfrog, "
                            "predictor_corrector or rk4)"
                  : fixed ? "the result is degraded; lower time.dt or set time.dt = 0 (adaptive)"
                          : "the result is degraded; lower time.cfl");
    warn("energy", -1, what, step, t, true);  // the message keeps the largest drift so far
  }
}

}  // namespace sph
