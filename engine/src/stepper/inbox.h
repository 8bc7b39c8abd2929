// Channels 1 and 2 of the stepper: the params mailbox (latest whole Params + version) and the command
// queue. Written by the GUI thread, taken whole by the engine thread between steps. One mutex guards
// both, so a command that carries params (reset, load) and its mailbox version are seen together.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/push.h"

namespace sph::detail {

struct Command {
  enum class Kind {
    Reset,             ///< rebuild the World with `config.params` (current scene and values)
    Load,              ///< build the World from `config`
    Pause,
    Resume,
    StepOnce,
    SetSceneValue,     ///< `name` = `value`, then rebuild
    SetRealTimeFactor, ///< `value` simulated seconds per wall second (0 = as fast as possible)
    SetStopAtEnd,      ///< `flag`
    SetPauseAt,        ///< `value`: pause when a step reaches this time (<= 0: never)
    SetRecordInterval, ///< `value` [time units], 0 = stop recording
    SetTreeProbe,      ///< `value`: the particle (snapshot index) whose tree walk frames carry; < 0 = none
    SetCompare,        ///< `names`: run B's overrides (key=value); empty = stop comparing
    SetSweep,          ///< `name`: the key, `names`: its values (one run each); empty = stop the sweep
    SetInspect,        ///< `value`: the particle id frames inspect; < 0 = none
    SaveState,         ///< write a checkpoint of the World to the file `name` (sph/checkpoint.h)
    LoadState,         ///< build the World from `config` and take over the saved state `state` (from `name`)
    SetPush,           ///< `push`: the user's push from the next step on (inactive = none)
  };
  Kind kind = Kind::Pause;
  RunConfig config;                 ///< Reset (params only) and Load
  std::uint64_t params_version = 0; ///< Reset, Load: mailbox version of the params they carry
  std::string name;
  std::vector<std::string> names;
  double value = 0.0;
  bool flag = false;
  std::string state;                ///< LoadState: World::save_state bytes
  Push push;                        ///< SetPush
};

/// What the engine thread takes in one go.
struct InboxBatch {
  std::vector<Command> commands;  ///< in posting order
  bool has_params = false;        ///< the mailbox holds a version newer than the one asked about
  Params params;
  std::uint64_t params_version = 0;
  bool stop = false;
};

class Inbox {
 public:
  /// GUI: replaces the mailbox content; returns the new version.
  std::uint64_t post_params(const Params& p);
  /// GUI: queues a command.
  void push(Command c);
  /// GUI: posts p and queues c (with c.params_version set to p's version) atomically; returns it.
  std::uint64_t push_with_params(Command c, const Params& p);
  /// Asks the engine thread to finish.
  void request_stop();
  bool stop_requested();

  /// Engine: takes the queued commands and, if newer than `adopted`, the mailbox params.
  InboxBatch take(std::uint64_t adopted);
  /// Engine: waits until something is posted (or until `deadline`).
  void wait();
  void wait_until(std::chrono::steady_clock::time_point deadline);

 private:
  bool pending() const { return !commands_.empty() || version_ > seen_ || stop_; }

  std::mutex mutex_;
  std::condition_variable wake_;
  Params params_;
  std::uint64_t version_ = 0;  // last posted
  std::uint64_t seen_ = 0;     // last version handed to take()
  std::vector<Command> commands_;
  bool stop_ = false;
};

}  // namespace sph::detail
