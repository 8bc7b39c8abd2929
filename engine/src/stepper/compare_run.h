// A run that follows the first World (run A) on the engine thread: run B of an A/B comparison, or one run
// of a parameter sweep (follower_runs.h). Built from A's scene, params and scene values with its overrides
// applied, stepped to A's times, following A's posted params (with its overrides kept), sampled into a
// history at A's sampling times.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "history.h"
#include "sph/compare.h"
#include "sph/stepper.h"
#include "sph/world.h"

namespace sph::detail {

class CompareRun {
 public:
  bool on() const { return world_ != nullptr; }
  const World* world() const { return world_.get(); }
  const std::vector<std::string>& overrides() const { return overrides_; }

  /// Builds B from A's config (at t = 0, or from `state` (World::save_state) when A was loaded from one:
  /// both then go on from the same particles; its history starts empty: sample() with A's first sample);
  /// false with *err (the comparison is then off). `name` names it in messages ("run B", "sweep run").
  bool start(const RunConfig& a, const std::vector<std::string>& overrides, std::string* err,
             const std::string* state = nullptr, const std::string& name = "run B");
  /// Rebuilds B with the same overrides from A's new config (a reset, a load, a scene value, a state).
  bool restart(const RunConfig& a, std::string* err, const std::string* state = nullptr) {
    return start(a, std::vector<std::string>(overrides_), err, state, std::string(name_));
  }
  void stop();
  /// B adopts A's params with its overrides applied again; false with *err if B cannot run them.
  bool follow(const Params& a, std::string* err);
  enum class Advance { Done, Behind, Failed };
  /// Steps B to time t, asking `interrupted` before each step: Done at t, Behind when it said stop first
  /// (B goes on from there on the next call), Failed with *err naming run B if it diverged or failed.
  Advance advance_to(double t, std::string* err, const std::function<bool()>& interrupted = {});
  /// "run B (...) cannot keep up: ..." for a B still behind A's time t after `budget` seconds.
  std::string too_slow(double t, double budget) const;
  void sample();                   ///< one history sample (call with A's)
  void fill(CompareFrame& f) const;  ///< everything but the inspection

 private:
  std::string label() const;  ///< "run B (its overrides)" for messages
  std::unique_ptr<World> world_;
  std::string name_ = "run B";
  std::vector<std::string> overrides_;
  History history_;
};

}  // namespace sph::detail
