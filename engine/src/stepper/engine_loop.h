// The body of the stepper's engine thread: drains commands, adopts posted params, steps the World
// (paced to a real-time factor if asked), and publishes frames into the triple buffer. Owns the World;
// nothing here is touched by another thread except through the Inbox and the TripleBuffer.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

#include "follower_runs.h"
#include "history.h"
#include "inbox.h"
#include "inspect_cache.h"
#include "rate_meter.h"
#include "sph/stepper.h"
#include "sph/trail_log.h"
#include "sph/world.h"
#include "triple_buffer.h"

namespace sph::detail {

class EngineLoop {
 public:
  EngineLoop(const StepperOptions& options, Inbox& inbox, TripleBuffer<StepperFrame>& out,
             std::atomic<std::uint64_t>& published)
      : options_(options), inbox_(inbox), out_(out), published_(published), record_every_(options.record_every) {}

  /// Runs until the inbox asks to stop.
  void run();

 private:
  using Clock = std::chrono::steady_clock;

  /// t has reached target (up to rounding of a sum of steps).
  static bool reached(double t, double target) { return t >= target - 1e-12 * std::max(1.0, std::abs(target)); }

  void apply(const Command& c);          // one command; true state changes only
  void set_scene_value(const std::string& name, double value);  // scene.NAME = value, then rebuild
  void adopt(const InboxBatch& b);       // mailbox params
  /// New World (with `state`: restored from a checkpoint, World::restore_state); keeps the old one if
  /// the build or the restore throws.
  void rebuild(const RunConfig& cfg, const std::string* state = nullptr, const std::string& from = "");
  void save_state(const std::string& path);  // a checkpoint of world_ (engine_state.cpp)
  void check_loaded_state();             // a restored state that holds a divergence is shown diverged
  void step();                           // one World::step with its bookkeeping
  bool follow();                         // the follower runs to A's time; false: stopping, publish nothing
  void start_recording(double every);
  void start_compare(const std::vector<std::string>& overrides);  // A and B from t = 0; empty: stop
  void start_sweep(const std::string& key, const std::vector<std::string>& values);  // A and the sweep from t = 0
  bool restart_a();                      // A from t = 0 with its current params, followers stopped
  // whether a World is loaded and each run's overrides fit it; else false with error_ ("WHAT: ...")
  bool can_follow(const char* what, const std::vector<std::vector<std::string>>& runs);
  void sample_history();
  void publish(int record_index = -1);
  bool stepping() const { return world_ && !diverged_ && (running_ || single_steps_ > 0); }
  void anchor_pacing();                  // real-time pacing restarts from (now, t)

  StepperOptions options_;
  Inbox& inbox_;
  TripleBuffer<StepperFrame>& out_;
  std::atomic<std::uint64_t>& published_;

  std::unique_ptr<World> world_;
  RunConfig cfg_;                      // of world_ (or of the failed first build)
  std::uint64_t world_serial_ = 0, serial_ = 0, adopted_ = 0;
  bool running_ = false, at_end_ = false, stop_at_end_ = true, diverged_ = false;
  int single_steps_ = 0;
  double pause_at_ = 0.0;              // pause when a step crosses this time (<= 0: never); Resume runs on
  std::int64_t tree_probe_ = -1;       // particle whose tree walk the frames carry (-1: none)
  std::int64_t diverged_particle_ = -1, diverged_step_ = -1;
  std::string error_;
  std::string notice_;                 // the last state saved or loaded
  double rtf_ = 0.0;                   // real-time factor (0 = as fast as possible)
  Clock::time_point pace_wall_;        // pacing anchor: wall time ...
  double pace_t_ = 0.0;                // ... and simulated time
  Clock::time_point last_publish_;
  double record_every_ = 0.0, record_t0_ = 0.0;
  int record_next_ = 0;                // index of the next recording time
  bool record_held_ = false;           // a recording frame waits to be read
  int emit_record_ = -1;               // recording index to publish after the current commands
  History history_;
  TrailLog trails_;                    // orbit trails of few-body scenes, sampled every step
  RateMeter meter_;
  FollowerRuns followers_;             // run B of an A/B comparison, or a sweep's runs (off unless asked for)
  InspectCache inspect_, inspect_b_;   // the inspected particle in run A and in run B
};

}  // namespace sph::detail
