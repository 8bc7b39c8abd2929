// The engine on its own thread, for interactive programs (MuJoCo simulate-style). The caller (the GUI
// thread) reaches the World only through three channels:
//   1. params mailbox  - post_params(): a whole Params copy (mutex + version); adopted at the top of the
//                        next step with World::set_params;
//   2. command queue   - reset, load, pause/resume, single step, scene values (rebuild), pacing,
//                        recording: drained between steps, in order;
//   3. snapshot buffer - latest(): a triple buffer of StepperFrame; neither side waits for the other,
//                        and everything in one frame (snapshot, diagnostics, params) belongs together.
// Headless runs and tests do not need this: they call World::step() directly.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/density.h"
#include "sph/diagnostics.h"
#include "sph/inspect.h"
#include "sph/push.h"
#include "sph/run_warning.h"
#include "sph/snapshot.h"

namespace sph {

struct StepperOptions {
  int threads = 0;                        ///< OpenMP threads of the engine thread; 0 = OpenMP's default
  double publish_interval = 1.0 / 120.0;  ///< least wall time between routine publications while running [s]
  bool start_running = true;              ///< step as soon as the first scene is built
  double record_every = 0.0;              ///< record from t = 0 of the first scene (see set_record_interval)
  int nice = 0;                           ///< Linux: niceness added to the engine thread (and the OpenMP team it
                                          ///< starts), e.g. to keep a display fluid when the engine uses every core
  double compare_budget = 10.0;           ///< an A/B run B that needs longer than this to follow one step of
                                          ///< run A (its time step collapsed) ends the comparison [s]
};

/// One point of the running diagnostics, for plots against simulated time.
struct HistorySample {
  double t = 0.0;                             ///< simulated time
  double E_kin = 0.0, E_int = 0.0, E_pot = 0.0, E_tot = 0.0;  ///< energies (seed 000 eqs. 3.4.4-3.4.5)
  double P = 0.0;                             ///< |linear momentum| (seed 000 eq. 3.4.1)
  std::vector<double> ref;                    ///< the reference's values (StepperFrame::ref_columns)
};

/// The second run of an A/B comparison (Stepper::set_compare): the first run's scene and parameters
/// with `overrides` applied, started with it from t = 0 and stepped to the same times.
struct CompareFrame {
  std::vector<std::string> overrides;  ///< key=value pairs run B differs by, e.g. "kernel.type=M6"
  Snapshot snapshot;
  Diagnostics diagnostics;
  std::vector<double> ref_values;      ///< its reference values (the columns are the first run's)
  std::vector<HistorySample> history;  ///< sampled with the first run's history, at the same times
  std::vector<RunWarning> warnings;
  RunConfig config;
  std::optional<Inspection> inspection;  ///< the inspected id in run B (Stepper::set_inspect)
};

/// What the engine thread publishes. Everything here describes the same instant of the same World.
struct StepperFrame {
  std::uint64_t serial = 0;        ///< publication counter, increasing
  std::uint64_t world_serial = 0;  ///< which World: incremented by every load, reset and rebuild;
                                   ///< step and time never decrease within one world_serial
  Snapshot snapshot;               ///< particles for the renderer (count == x.size())
  Diagnostics diagnostics;         ///< energies, momenta, h-iterations, mean neighbours
  bool has_reference = false;      ///< the scene has a reference (exact solution, ODE, measured data)
  std::vector<RefColumn> ref_columns;  ///< its columns (measurements, exact values, error norms)
  std::vector<double> ref_values;  ///< their values now
  int ref_primary = -1;            ///< the column plotted as "the error"
  std::vector<std::pair<int, int>> ref_series;  ///< measured/exact column pairs plotted together
  std::vector<std::string> stages; ///< the stages the World runs, in pipeline order
  DensityStats density;            ///< last density solve
  std::vector<RunWarning> warnings;  ///< what this World's run has tolerated so far (RunChecks::warnings)
  RunConfig config;                ///< scene, adopted params and scene values of this World
  std::uint64_t params_version = 0;///< the last mailbox version adopted (0 = none yet)
  std::vector<HistorySample> history;  ///< this World's diagnostics against time (decimated, <= 2048)

  bool running = false;            ///< stepping (false: paused, at t_end, diverged or failed)
  bool at_end = false;             ///< paused because t reached params.t_end
  double real_time_factor = 0.0;   ///< simulated seconds per wall second; 0 = as fast as possible
  double steps_per_second = 0.0;   ///< measured over the last ~0.5 s of stepping [1/s]
  double particle_steps_per_second = 0.0;  ///< steps_per_second x particles [1/s]

  bool diverged = false;           ///< World::step threw DivergedError (the stepper paused)
  std::int64_t diverged_particle = -1, diverged_step = -1;  ///< its particle id and step
  std::string error;               ///< the divergence or failure message (empty if none)
  std::string notice;              ///< the last state saved or loaded ("saved state to FILE"), empty if none

  double record_every = 0.0;       ///< recording interval (0 = not recording) [time units]
  int record_index = -1;           ///< >= 0: this frame lands on recording time t0 + index x every

  bool comparing = false;          ///< `compare` holds run B of an A/B comparison
  CompareFrame compare;
  std::string sweep_key;           ///< the key of a parameter sweep ("" = none; Stepper::set_sweep)
  std::vector<CompareFrame> sweep; ///< its runs (each with overrides {key=value}), at this frame's time
  /// Report::inspect of the particle asked for (Stepper::set_inspect); while running refreshed at most 4
  /// times a second and within a tenth of the engine's time (its `step` says which state it explains),
  /// at every new state otherwise.
  std::optional<Inspection> inspection;
  Push push;                       ///< the user's push acting now (World::push; inactive = none)
  std::vector<PushEvent> pushes;   ///< push changes logged by this World so far, with their steps
                                   ///< (World::pushes): a PushReplay of them repeats the run
};

class Stepper {
 public:
  /// Starts the engine thread and queues load(cfg); latest() is nullptr until the World is built.
  explicit Stepper(const RunConfig& cfg, StepperOptions options = {});
  /// Stops and joins the engine thread.
  ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  // --- channel 1: params mailbox -------------------------------------------------------------------
  /// Hands over a whole Params copy; returns its version (1, 2, ...). Adopted before the next step.
  std::uint64_t post_params(const Params& p);

  // --- channel 2: commands (queued, drained between steps, in order) -------------------------------
  /// Rebuilds the World from the current scene and scene values with these params (posted too: the
  /// return value is their mailbox version).
  std::uint64_t reset(const Params& p);
  /// Replaces the scene (its params are posted too; returns their version). A failing build keeps the
  /// old World and reports the error in the next frame.
  std::uint64_t load(const RunConfig& cfg);
  void pause();
  void resume();
  /// Pauses and advances exactly one step.
  void step_once();
  /// Sets a scene value ("n_left", not "scene.n_left") and rebuilds the World.
  void set_scene_value(const std::string& name, double value);
  /// Simulated seconds per wall second; 0 = as fast as possible.
  void set_real_time_factor(double f);
  /// Pause when t reaches params.t_end (default on).
  void set_stop_at_end(bool on);
  /// Pause when a step reaches time t (the step is shortened to land on it); Resume runs on past it, and
  /// a run reset to before t pauses there again. t <= 0: never (the default).
  void set_pause_at(double t);
  /// Frames carry the Barnes-Hut cells of particle k's walk (Snapshot::tree_cells) for the tree
  /// overlay; k < 0 = none (the default).
  void set_tree_probe(std::int64_t k);
  /// Records at fixed simulated-time intervals: from now on, steps land on t0 + k x every and each
  /// such frame is published with record_index = k and held until latest() has taken it. 0 = stop.
  void set_record_interval(double every);
  /// A/B comparison: rebuilds the World from t = 0 with its current params and scene values, beside a
  /// second one with `overrides` (key=value, as `--set`: "kernel.type=M6", "visc.alpha=0",
  /// "scene.n_left=800") applied; both are stepped to the same times and posted params reach both (B
  /// keeps its overrides). An override the scene refuses leaves everything as it was and reports the
  /// error. Empty: the comparison stops (the first World runs on).
  void set_compare(const std::vector<std::string>& overrides);
  /// A parameter sweep: rebuilds the World from t = 0 with its current params and scene values, beside
  /// one more run per value with key=value applied (as set_compare's run B; at most 5); all are stepped to
  /// the same times and frames carry them in `sweep`. It replaces an A/B comparison (and set_compare
  /// replaces it). A value the scene refuses leaves everything as it was and reports the error. No
  /// values: the sweep stops.
  void set_sweep(const std::string& key, const std::vector<std::string>& values);
  /// Frames carry Report::inspect(id) (and run B's, when comparing); id < 0: none.
  void set_inspect(std::int64_t id);
  /// Writes the World's whole state to `path` (a checkpoint, as `sph run --checkpoint-every` writes:
  /// `sph resume` and load_state read it); the frame's notice or error says how it went.
  void save_state(const std::string& path);
  /// Replaces the World by the one checkpoint `path` holds (read it with read_checkpoint; `cfg` is its
  /// configuration, whose params are posted: the return value is their version). A state that does not
  /// fit keeps the old World and reports the error.
  std::uint64_t load_state(const std::string& path, const RunConfig& cfg, const std::string& state);
  /// The user's push (sph/push.h) on run A from its next step on; an inactive push ends it. Logged by
  /// the World with its step (World::pushes), so the run can be replayed.
  void set_push(const Push& push);

  // --- channel 3: snapshots --------------------------------------------------------------------------
  /// The newest published frame, or nullptr before the first. The frame stays valid and unchanged until
  /// the next call. One reader thread only.
  const StepperFrame* latest();
  /// Frames published so far (any thread; for tests and statistics).
  std::uint64_t published() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph
