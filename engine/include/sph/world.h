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
#include "sph/run_warning.h"
#include "sph/snapshot.h"

namespace sph {

class Pipeline;
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

  /// One step of the adaptive (or fixed) dt, shortened to at most dt_max. Throws DivergedError.
  void step(double dt_max = 1e300);
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

  /// What the run has tolerated so far (empty for a clean run), in the order first found.
  const std::vector<RunWarning>& warnings() const { return warnings_; }

  /// Evaluate the stages for the current state (done automatically by step()).
  void evaluate();

 private:
  StageContext context() const;
  /// Ghosts and neighbour lists for the current state (the start of every evaluation).
  void prepare_neighbours();
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
  NeighbourList wide_;                       ///< Verlet lists (fixed h, no ghosts), nl_ is filtered from them
  bool lists_valid_ = false;                 ///< wide_ may be reused
  std::array<std::vector<double>, 3> x_built_;  ///< positions when the lists were built
  double verlet_margin_ = 0.0;               ///< twice the displacement the lists tolerate [length]
  double t_ = 0.0, dt_last_ = 0.0;
  double dt_first_ = 0.0;     ///< the first adaptive dt (a collapse far below it is a blow-up)
  double energy_scale_ = -1.0, energy0_ = 0.0;  ///< |E_kin| + |E_int| + |E_pot| and E_tot after step 1
  double worst_drift_ = 0.0;                    ///< the largest energy drift warned about
  WallCrossings crossings_;                     ///< since the last check_walls()
  std::vector<RunWarning> warnings_;
  std::int64_t step_ = 0, evaluations_ = 0;
  bool current_ = false;      ///< rates belong to the current state
  bool rates_known_ = false;  ///< signal speeds from some evaluation under the current params (for dt)
};

}  // namespace sph
