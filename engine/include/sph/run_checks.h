// The checks after each step that keep a run from going bad silently, and the warnings they leave:
// non-finite state, a collapsing timestep or a finite energy blow-up (stop), particles escaping
// through walls (stop) or crossing them, energy drift, an h solve that did not converge, a run past
// its reference (warn); at the start, a fixed timestep too long for a pericentre passage of point
// masses (warn). Owned by World; read through World::checks().
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/density.h"
#include "sph/diagnostics.h"
#include "sph/domain.h"
#include "sph/diverged.h"
#include "sph/reference.h"
#include "sph/run_warning.h"

namespace sph {

class ByteReader;
class ByteWriter;
class Reference;

class RunChecks {
 public:
  /// The most point masses whose every pair the checks look at (the few bodies of the N-body scenes):
  /// their energy every step, their orbits' pericentres at the start.
  static constexpr std::size_t kFewBodies = 64;
  /// What the run has tolerated so far (empty for a clean run), in the order first found.
  const std::vector<RunWarning>& warnings() const { return warnings_; }

  /// Throws DivergedError if a position, velocity, density, h, u, P or c of `p` is non-finite or beyond
  /// single precision (at `step`, time t).
  static void check_finite(const Particles& p, std::int64_t step, double t);
  /// The id of the particle with the largest acceleration (lowest index among equals).
  static std::int64_t fastest_particle(const Particles& p);

  /// Adds wall crossings of one application of the boundaries (for check_walls()).
  void tally(const WallCrossings& w);
  /// Forgets the crossings tallied (storage indices changed).
  void forget_crossings() { crossings_ = WallCrossings{}; }
  /// The blow-up guards measure from the next step on (new parameters or a push may change dt and the
  /// energies legitimately).
  void restart_guards() { dt_first_ = 0.0; energy_scale_ = -1.0; }
  /// Whether check_energy has taken its reference energy since the start or the last restart_guards().
  bool energy_armed() const { return energy_scale_ >= 0.0; }

  /// Throws when the step's dt is not finite and positive, or when the adaptive dt (dt_free; checked
  /// when `adaptive`) collapsed far below the first step's.
  void check_dt(double dt, double dt_free, bool adaptive, const Particles& p, std::int64_t step, double t);
  /// Throws when a particle escaped through a wall; warns when particles had to be reflected back.
  void check_walls(const Particles& p, const Params& prm, std::int64_t step, double t);
  /// A scene with wall particles: warns (kind "domain") when fluid particles are outside the domain box
  /// along an open axis: they went through a wall or were flung far beyond the scene (run_checks_domain.cpp).
  void check_domain(const Particles& p, const Domain& d, std::int64_t step, double t);
  /// Warns when the h solve did not converge for some particles.
  void check_h_solve(const DensityStats& d, std::int64_t step, double t);
  /// DFSPH: a pressure solve that hit its iteration cap (the density error is above its tolerance).
  void check_projection(const ProjectionStats& s, const LiquidParams& l, std::int64_t step, double t);
  /// Throws DivergedError when E_tot has grown far beyond its initial scale (a finite blow-up); warns
  /// when a scene that conserves energy drifts beyond its SceneSpec::energy_bound. `diagnostics` is
  /// called only on the steps that check (with `now`, this one: an output of a gravity scene).
  void check_energy(const RunConfig& cfg, const std::function<Diagnostics()>& diagnostics, const Particles& p,
                    std::int64_t step, double t, bool now = false);
  /// Warns when the run passes the time its reference applies to.
  void check_reference(const Reference* ref, std::int64_t step, double t);
  /// At the start and after new parameters: warns (kind "assumption") when a value the scene's reference
  /// assumes is outside its range (SceneSpec::assumptions), naming the key (run_checks_reference.cpp).
  void check_assumptions(const RunConfig& cfg);
  /// At an output: warns (kind "accuracy:COLUMN", from its first crossing) when an error norm of the
  /// reference, while it applies, is beyond the scene's bound for it (SceneSpec::error_bounds).
  void check_error_bounds(const RunConfig& cfg, const Reference* ref, const std::vector<RefColumn>& columns,
                          const std::vector<double>& values, std::int64_t step, double t);
  /// At the start: warns when a fixed time.dt is too large for the pericentre passage of a bound pair of
  /// point masses (h = 0, a few bodies) to keep the scene within its energy bound (run_checks_timestep.cpp).
  void check_pericentres(const RunConfig& cfg, const Particles& p);
  /// Individual time steps: warns (kind "timestep") when `too_long` particle steps took the block's
  /// shortest level though they wanted less than half of it, since the last call.
  void check_levels(std::int64_t too_long, int levels, std::int64_t step, double t);
  /// A gravity scene whose energy drifted beyond its bound: the run's result is not to be trusted (the
  /// headless program exits non-zero after writing it).
  bool energy_beyond_bound(const RunConfig& cfg) const {
    return cfg.params.physics.gravity != GravityType::None && cfg.scene->energy_bound > 0.0 &&
           worst_drift_ > cfg.scene->energy_bound;
  }

  /// Checkpoint layout: the guards' scales, the crossings and the warnings (CheckpointError on a misfit).
  void save(ByteWriter& w) const;
  void restore(ByteReader& r);

 private:
  /// Adds a warning, or counts one more of its kind (and with `latest`, takes the new message).
  void warn(const std::string& kind, std::int64_t particle, const std::string& message, std::int64_t step,
            double t, bool latest = false);

  double dt_first_ = 0.0;                        ///< the first adaptive dt (a collapse far below it is a blow-up)
  double energy_scale_ = -1.0, energy0_ = 0.0;  ///< |E_kin| + |E_int| + |E_pot| and E_tot after step 1
  double worst_drift_ = 0.0;                     ///< the largest energy drift warned about
  WallCrossings crossings_;                      ///< since the last check_walls()
  std::vector<RunWarning> warnings_;
};

}  // namespace sph
