// The simulation: particles, boundaries, the scene's pipeline of stages and an integrator. Headless
// runs and tests call step() directly (no threads); the GUI's stepper thread owns one World.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/density.h"
#include "sph/diagnostics.h"
#include "sph/inspect.h"
#include "sph/integrator.h"
#include "sph/kernel.h"
#include "sph/neighbours.h"
#include "sph/push.h"
#include "sph/run_warning.h"
#include "sph/snapshot.h"

namespace sph {

class Pipeline;
class TeamChooser;
struct EvalStats;
struct StageContext;

/// Wall time spent in one part of the evaluation since the world was built (or the pipeline changed):
/// "neighbours" (ghosts and lists), then each stage by name. For benchmarks and the GUI's cost view.
struct StageTiming {
  std::string name;
  double seconds = 0.0;
  std::int64_t calls = 0;
};

/// The run cannot go on: a NaN or inf appeared in the state (which particle (id), which field, at which
/// step), or a check found a blow-up that is still finite (the reason says which).
struct DivergedError : std::runtime_error {
  DivergedError(std::int64_t particle, std::int64_t step, double t, const std::string& field);
  /// A finite blow-up: `reason` is the whole explanation (it names the particle where there is one).
  DivergedError(std::int64_t particle, std::int64_t step, double t, const std::string& field, const std::string& reason);
  std::int64_t particle, step;
  double t;
  std::string field;
};


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
  const RunConfig& config() const { return cfg_; }
  const SceneSpec& scene() const { return *cfg_.scene; }

  /// One step of the adaptive (or fixed) dt, shortened to at most dt_max. Throws DivergedError. Runs on
  /// a team of at most the caller's OpenMP thread count: by default the faster of one thread and the
  /// full team, measured every few hundred steps (core/team_size.h); results are the same either way.
  void step(double dt_max = 1e300);
  /// Off: every step uses the caller's full OpenMP team (tests comparing thread counts).
  void set_adaptive_threads(bool on) { adaptive_threads_ = on; }
  /// The team the last step ran on.
  int last_team() const { return last_team_; }
  /// Steps until time t (the last step is shortened to land on t exactly).
  void advance_to(double t);
  /// The timestep the next step would take (from the last force evaluation).
  double next_dt();

  double time() const { return t_; }
  std::int64_t steps() const { return step_; }
  double last_dt() const { return dt_last_; }
  /// The particles, in the engine's storage order (spatially sorted: it changes every few steps).
  const Particles& particles() const { return p_; }
  /// Storage indices of the real particles in increasing id: outputs list particles in this order, so
  /// a particle keeps its row whatever the storage order.
  const std::vector<std::uint32_t>& by_id() const { return by_id_; }
  const Domain& domain() const { return domain_; }
  const Kernel& kernel() const { return kernel_; }
  double eta() const;  ///< effective eta (the kernel's default if kernel.eta == 0)
  double spacing() const { return spacing_; }  ///< the scene's initial particle spacing
  double wall_strength() const { return wall_strength_; }  ///< the scene's Lennard-Jones D (walls.D = 0)
  const DensityStats& density_stats() const;
  std::size_t correction_fallbacks() const;  ///< particles whose gradient correction fell back (last evaluation)
  std::int64_t evaluations() const { return evaluations_; }
  /// Names of the stages that run, in pipeline order.
  std::vector<std::string> stage_names() const;
  /// Time per part of the evaluation: [0] is the neighbour search, then the stages in pipeline order.
  const std::vector<StageTiming>& timings() const { return timings_; }
  /// Candidate pairs in the current neighbour lists (self included).
  std::size_t neighbour_pairs() const;
  /// Neighbour-list builds since the world was made (the lists are kept between evaluations while
  /// they fit: see World::prepare_neighbours).
  std::int64_t list_builds() const { return list_builds_; }
  /// Off: new neighbour lists at every evaluation (tests comparing against the kept lists).
  void set_list_reuse(bool on) { reuse_lists_ = on; }
  /// Evaluations whose density solve found an h beyond its list and ran again on new lists.
  std::int64_t h_overflows() const { return h_overflows_; }

  Diagnostics diagnostics() const;
  bool has_reference() const { return reference_ != nullptr; }
  const Reference* reference() const { return reference_.get(); }
  /// The reference's columns and their values now (empty without a reference).
  const std::vector<RefColumn>& reference_columns() const { return ref_columns_; }
  std::vector<double> reference_values() const;
  /// One reference value by column name; throws std::out_of_range if there is no such column.
  double reference_value(const std::string& name) const;
  /// Copy of what a viewer needs (floats): positions, h, kinds, every display field, reference curves.
  Snapshot snapshot() const;
  /// The Barnes-Hut cells the walk of particle k (a snapshot index) takes now, at the current theta and
  /// guard (the tree overlay); empty when the scene's gravity is not the tree or k is out of range.
  std::vector<TreeCell> tree_cells(std::size_t k) const;
  /// Particle `id` taken apart (sph/inspect.h): its fields, neighbours and the terms of its equations,
  /// re-evaluated at the current state on a copy of the particles (the run itself is not changed; costs
  /// one evaluation). nullopt if there is no such particle.
  std::optional<Inspection> inspect(std::int64_t id) const;

  /// Sets the user's push (sph/push.h) from the next step on, at each of its force evaluations; an
  /// inactive push ends it. A change is logged with the step it applies from (pushes()), re-evaluates the
  /// rates before the next step and restarts the energy guards (a push adds or removes energy). While a
  /// push is active, dt <= cfl x tau. Setting the push already set changes nothing.
  void set_push(const Push& push);
  const Push& push() const { return push_; }
  /// Every push change so far, in order: a PushReplay of them repeats the run.
  const std::vector<PushEvent>& pushes() const { return pushes_; }

  /// What the run has tolerated so far (empty for a clean run), in the order first found.
  const std::vector<RunWarning>& warnings() const { return warnings_; }

  /// Evaluate the stages for the current state (done automatically by step()).
  void evaluate() { evaluate(t_); }

  /// Everything later steps depend on (particles with their ghosts, kept neighbour lists, integrator
  /// history, stage state, counters, warnings), bit for bit, for a checkpoint (sph/checkpoint.h).
  std::string save_state() const;
  /// Takes over a state save_state() gave, in a world built from the same configuration: the steps
  /// that follow are bitwise those the saved world would have taken. Throws CheckpointError (naming
  /// `what`) if the state does not fit this world; the world is then unusable and must be dropped.
  void restore_state(const std::string& bytes, const std::string& what);
  /// The check after every step, on demand (e.g. for a restored state, which may have been saved from a
  /// diverged run): throws DivergedError if a position, velocity, density, h, u or P is non-finite or
  /// beyond single precision.
  void check_state() const { check_finite(); }

 private:
  StageContext context() const;
  /// Evaluates the state an integrator put at time t_eval (within the step).
  void evaluate(double t_eval);
  /// Ghosts and neighbour lists for the current state (the start of every evaluation): the lists of
  /// an earlier evaluation while they fit, else new ones.
  void prepare_neighbours();
  /// No particle has moved more than half the lists' skin since they were built, and no h outgrew
  /// its list (world_lists.cpp).
  bool lists_fit() const;
  /// Moves the periodic coordinates wrapped since the build back to the build's image (unwrapped_).
  void unwrap();
  /// Restores the coordinates unwrap() moved.
  void rewrap();
  /// Stage actions due after a completed step (e.g. density re-initialisation).
  void after_step();
  void reset_timings();
  /// Replaces the real particles by a stage's new set of another size (see Stage::take_resampled).
  void adopt(Particles&& fresh);
  /// Permutes the particle arrays into Morton order (the fluid; walls once) and updates by_id().
  void reorder();
  /// Boundaries (wrap, reflect) with their wall crossings tallied for check_walls().
  void bound();
  void check_finite() const;
  /// Throws DivergedError when E_tot has grown far beyond its initial scale (a finite blow-up); warns
  /// when a scene that conserves energy drifts beyond its SceneSpec::energy_bound.
  void check_energy();
  /// Throws when a particle escaped through a wall; warns when particles had to be reflected back.
  void check_walls();
  void check_h_solve();    ///< warns when the h solve did not converge for some particles
  void check_reference();  ///< warns when the run passes the time its reference applies to
  /// Adds a warning, or counts one more of its kind (and with `latest`, takes the new message).
  void warn(const std::string& kind, std::int64_t particle, const std::string& message, bool latest = false);
  /// The id of the particle with the largest acceleration (lowest index among equals).
  std::int64_t fastest_particle() const;
  PhaseSpace phase_space();
  void advance(double dt_max);  ///< the step itself (step() chooses its team)

  RunConfig cfg_;
  Kernel kernel_;
  Particles p_;
  Domain domain_;
  double spacing_ = 0.0, wall_strength_ = 0.0;
  std::unique_ptr<Pipeline> pipeline_;
  FieldSet start_shared_;  ///< copied to the ghosts before the stages run (mass, h, evolved state)
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<Reference> reference_;
  std::vector<RefColumn> ref_columns_;
  NeighbourList nl_;
  std::unique_ptr<EvalStats> stats_;
  std::vector<double> h_limit_;
  std::vector<StageTiming> timings_;
  std::vector<std::uint32_t> by_id_;
  NeighbourList exact_;                      ///< nl_ filtered to the support, for stages that ask for it
  bool lists_valid_ = false;                 ///< nl_ may be reused (while lists_fit())
  bool reuse_lists_ = true;                  ///< set_list_reuse
  std::array<std::vector<double>, 3> x_built_;  ///< real particles' positions when the lists were built
  std::vector<double> reach_h_;              ///< h_limit of every particle and ghost (the build's scratch)
  /// A periodic coordinate wrapped since the lists were built, moved back to its image of the build for
  /// the stages and restored after them (x is its wrapped value).
  struct Unwrapped {
    std::uint32_t i;
    int axis;
    double x;
  };
  std::vector<Unwrapped> unwrapped_;
  std::int64_t list_builds_ = 0;             ///< neighbour-list builds so far
  std::int64_t h_overflows_ = 0;             ///< evaluations run again because an h outgrew its list
  double t_last_eval_ = -1.0;  ///< time of the last evaluation (< 0: none under the current parameters)
  double since_ = 0.0;         ///< time from the last evaluation to the current one (0 when unknown)
  double t_ = 0.0, dt_last_ = 0.0;
  double dt_first_ = 0.0;     ///< the first adaptive dt (a collapse far below it is a blow-up)
  double energy_scale_ = -1.0, energy0_ = 0.0;  ///< |E_kin| + |E_int| + |E_pot| and E_tot after step 1
  double worst_drift_ = 0.0;                    ///< the largest energy drift warned about
  WallCrossings crossings_;                     ///< since the last check_walls()
  std::vector<RunWarning> warnings_;
  std::int64_t step_ = 0, evaluations_ = 0;
  std::unique_ptr<TeamChooser> team_;
  bool adaptive_threads_ = true;
  int last_team_ = 1;
  Push push_;                          ///< the user's push (inactive unless set)
  std::vector<PushEvent> pushes_;      ///< its changes, with their steps
  bool current_ = false;      ///< rates belong to the current state
  bool rates_known_ = false;  ///< signal speeds from some evaluation under the current params (for dt)
};

}  // namespace sph
