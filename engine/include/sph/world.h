// The simulation: particles, boundaries, the scene's pipeline of stages and an integrator. Headless
// runs and tests call step() directly (no threads); the GUI's stepper thread owns one World.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/diverged.h"
#include "sph/integrator.h"
#include "sph/kernel.h"
#include "sph/neighbour_cache.h"
#include "sph/push.h"
#include "sph/report.h"
#include "sph/run_checks.h"

namespace sph {

class BlockSteps;
class Pipeline;
class TeamChooser;
struct EvalStats;
struct StageContext;

/// The step's orchestration over the world's parts: the particle state and its fields (particles(),
/// by_id(), domain()), the neighbour cache (neighbours()), the run checks and their warnings (checks())
/// and what the run reports (report()); save_state/restore_state take all of them for a checkpoint.
class World {
 public:
  /// Builds the scene. Throws ConfigError if its physics is not a valid combination for the scene.
  explicit World(const RunConfig& cfg);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adopt new run parameters; live ones take effect at the next step (kernel, eta, alpha, the force
  /// formulation...). A change of physics rebuilds the pipeline and allocates the fields it adds.
  /// Throws ConfigError (and keeps the old parameters) if the physics is not valid for the scene.
  void set_params(const Params& p);
  const Params& params() const { return cfg_.params; }
  /// The scene (config().scene) and its resolved run parameters.
  const RunConfig& config() const { return cfg_; }

  /// One step of the adaptive (or fixed) dt, shortened to at most dt_max: to dt_max itself, or to half
  /// of dt_max where a whole step would leave a sliver before it (integrators/landing_step.h). Throws
  /// DivergedError. Runs on a team of at most the caller's OpenMP thread count: by default the faster of
  /// one thread and the full team, measured every few hundred steps (core/team_size.h); results are the
  /// same either way.
  void step(double dt_max = 1e300);
  /// Off: every step uses the caller's full OpenMP team (tests comparing thread counts).
  void set_adaptive_threads(bool on) { adaptive_threads_ = on; }
  /// The team the last step ran on.
  int last_team() const { return last_team_; }
  /// Steps until time t, landing on it exactly as step(t - time()) does; with `interrupted`, asks it
  /// before each step and returns false when it said stop short of t (the GUI's run B catching up with
  /// run A takes the user's commands between its steps).
  bool advance_to(double t, const std::function<bool()>& interrupted = {});
  /// The timestep the next step would take (from the last force evaluation).
  double next_dt();

  double time() const { return t_; }
  std::int64_t steps() const { return step_; }
  /// The particles, in the engine's storage order (spatially sorted: it changes every few steps).
  const Particles& particles() const { return p_; }
  /// Storage indices of the real particles in increasing id: outputs list particles in this order, so
  /// a particle keeps its row whatever the storage order.
  const std::vector<std::uint32_t>& by_id() const { return by_id_; }
  const Domain& domain() const { return domain_; }

  /// The neighbour lists kept between evaluations: their pairs, builds and h overflows.
  const NeighbourCache& neighbours() const { return lists_; }
  /// Off: new neighbour lists at every evaluation (tests comparing against the kept lists).
  void set_list_reuse(bool on) { lists_.set_reuse(on); }
  /// The checks after every step: warnings() is what the run has tolerated so far.
  const RunChecks& checks() const { return checks_; }
  /// Before an output is written: a gravity scene's energy checked now as well (RunChecks::check_energy;
  /// throws DivergedError on a blow-up, so the bad state is not written), and the reference's error
  /// norms against the scene's bounds.
  void check_output();
  /// The reference's error norms now (Report::reference_values) against the scene's bounds
  /// (RunChecks::check_error_bounds): for a view that has evaluated them already.
  void check_error_bounds(const std::vector<double>& values);
  /// What the run reports now (diagnostics, reference values, snapshots, the inspector, costs): a view
  /// valid until the world next changes.
  Report report() const;

  /// Sets the user's push (sph/push.h) from the next step on, at each of its force evaluations; an
  /// inactive push ends it. A change is logged with the step it applies from (pushes()), re-evaluates the
  /// rates before the next step and restarts the energy guards (a push adds or removes energy). While a
  /// push is active, dt <= cfl x tau. Setting the push already set changes nothing.
  void set_push(const Push& push);
  const Push& push() const { return push_; }
  /// Every push change so far, in order: a PushReplay of them repeats the run.
  const std::vector<PushEvent>& pushes() const { return pushes_; }

  /// Evaluate the stages for the current state (done automatically by step()).
  void evaluate() { evaluate(t_); }

  /// Everything later steps depend on (particles with their ghosts, kept neighbour lists, integrator
  /// history, stage state, counters, warnings), bit for bit, for a checkpoint (sph/checkpoint.h).
  std::string save_state() const;
  /// Takes over a state save_state() gave, in a world built from the same configuration: the steps
  /// that follow are bitwise those the saved world would have taken. Throws CheckpointError (naming
  /// `what`) if the state does not fit this world; the world is then unusable and must be dropped.
  void restore_state(const std::string& bytes, const std::string& what);

 private:
  StageContext context() const;
  double eta() const;  ///< effective eta (the kernel's default if kernel.eta == 0)
  /// Evaluates the state an integrator put at time t_eval (within the step).
  void evaluate(double t_eval);
  /// Ghosts and neighbour lists for the current state (the start of every evaluation): the lists of
  /// an earlier evaluation while they fit, else new ones (sph/neighbour_cache.h).
  void prepare_neighbours();
  /// Stage actions due after a completed step (e.g. density re-initialisation).
  void after_step();
  void reset_timings();
  /// Replaces the real particles by a stage's new set of another size (see Stage::take_resampled).
  void adopt(Particles&& fresh);
  /// Permutes the particle arrays into Morton order (the fluid; walls once) and updates by_id().
  void reorder();
  /// Boundaries (wrap, reflect) with their wall crossings tallied for the checks.
  void bound();
  /// The checks after a completed step.
  void check_step();
  PhaseSpace phase_space();
  void advance(double dt_max);  ///< the step itself (step() chooses its team)
  /// The next step's length: the stages' limit, at most dt_max, checked (RunChecks::check_dt) [time].
  double step_length(double dt_max);
  /// After a step of length dt: boundaries, time, step count, the stages' after-step actions, the checks.
  void end_step(double dt);
  /// The step with individual time steps (time.levels > 1): one sub-step of the block (block_steps.h).
  void advance_block(double dt_max);
  void advance_projected(double dt_max);  ///< the step of a pressure solve (Stage::projects; world_projected.cpp)
  /// Every fluid particle's wanted dt: cfl min(its stage limits, sqrt(h/|a|)) [time].
  void wanted_steps(std::vector<double>& want);
  /// The particle arrays of a checkpoint, checked against this world (world_state.cpp).
  void save_particles(ByteWriter& w) const;
  Particles read_particles(ByteReader& r, std::size_t bytes) const;
  /// The integrator history, reference and stage states of a checkpoint, then its end.
  void restore_stages(ByteReader& r);

  RunConfig cfg_;
  Kernel kernel_;
  Particles p_;
  Domain domain_;
  double spacing_ = 0.0, wall_strength_ = 0.0;
  std::unique_ptr<Pipeline> pipeline_;
  FieldSet start_shared_;  ///< copied to the ghosts before the stages run (mass, h, evolved state)
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<BlockSteps> block_;  ///< individual time steps (time.levels > 1), else null
  /// The block whose active particles the current evaluation is for (individual time steps), else
  /// null: every particle.
  BlockSteps* active_ = nullptr;
  std::unique_ptr<Reference> reference_;
  std::vector<RefColumn> ref_columns_;
  std::unique_ptr<EvalStats> stats_;
  std::vector<StageTiming> timings_;
  std::vector<std::uint32_t> by_id_;
  NeighbourCache lists_;
  RunChecks checks_;
  double t_last_eval_ = -1.0;  ///< time of the last evaluation (< 0: none under the current parameters)
  double since_ = 0.0;         ///< time from the last evaluation to the current one (0 when unknown)
  double t_ = 0.0, dt_last_ = 0.0;
  std::int64_t step_ = 0, evaluations_ = 0;
  std::int64_t updates_ = 0;  ///< particle evaluations: the fluid, or the active particles of a sub-step
  std::unique_ptr<TeamChooser> team_;
  bool adaptive_threads_ = true;
  int last_team_ = 1;
  Push push_;                          ///< the user's push (inactive unless set)
  std::vector<PushEvent> pushes_;      ///< its changes, with their steps
  bool current_ = false;      ///< rates belong to the current state
  bool rates_known_ = false;  ///< signal speeds from some evaluation under the current params (for dt)
};

}  // namespace sph
