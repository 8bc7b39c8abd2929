// The runs that follow run A on the engine thread: run B of an A/B comparison, or the runs of a parameter
// sweep (run A with key = each of the sweep's values). They start, rebuild, adopt A's params, step to A's
// time and sample together; one failure or one run that cannot keep up ends them all, saying which.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "compare_run.h"

namespace sph::detail {

class FollowerRuns {
 public:
  enum class Kind { None, Compare, Sweep };
  Kind kind() const { return kind_; }
  bool on() const { return kind_ != Kind::None; }
  std::size_t size() const { return runs_.size(); }
  const CompareRun& run(std::size_t i) const { return runs_[i]; }
  const std::string& sweep_key() const { return key_; }

  /// Run B with these overrides; false with *err (then off).
  bool start_compare(const RunConfig& a, const std::vector<std::string>& overrides, std::string* err);
  /// One run per value, each with key=value; false with *err (then off).
  bool start_sweep(const RunConfig& a, const std::string& key, const std::vector<std::string>& values,
                   std::string* err);
  /// Rebuilds every run from A's new config (CompareRun::restart); false with *err (then off).
  bool restart(const RunConfig& a, std::string* err, const std::string* state = nullptr);
  void stop();
  /// Every run adopts A's params with its overrides; the first refusal goes into *err.
  void follow(const Params& a, std::string* err);
  /// Steps every run to t (CompareRun::advance_to): Failed at the first run that failed, Behind at the
  /// first one still behind when `interrupted` said stop (*behind is its index), else Done.
  CompareRun::Advance advance_to(double t, std::string* err, const std::function<bool()>& interrupted,
                                 std::size_t* behind);
  void sample();

 private:
  Kind kind_ = Kind::None;
  std::vector<CompareRun> runs_;
  std::string key_;  // the sweep's key
};

}  // namespace sph::detail
