#include "follower_runs.h"

namespace sph::detail {

bool FollowerRuns::start_compare(const RunConfig& a, const std::vector<std::string>& overrides, std::string* err) {
  stop();
  runs_.resize(1);
  if (!runs_[0].start(a, overrides, err)) {
    stop();
    return false;
  }
  kind_ = Kind::Compare;
  return true;
}

bool FollowerRuns::start_sweep(const RunConfig& a, const std::string& key, const std::vector<std::string>& values,
                               std::string* err) {
  stop();
  if (values.empty() || values.size() > kMaxSweepRuns) {
    *err = "sweep: " + std::to_string(values.size()) + " values of " + key + " given; it takes 1 to " +
           std::to_string(kMaxSweepRuns) + " besides run A's own";
    return false;
  }
  runs_.resize(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!runs_[i].start(a, {key + "=" + values[i]}, err, nullptr, "sweep run")) {
      stop();
      return false;
    }
  kind_ = Kind::Sweep;
  key_ = key;
  return true;
}

bool FollowerRuns::restart(const RunConfig& a, std::string* err, const std::string* state) {
  for (CompareRun& r : runs_)
    if (!r.restart(a, err, state)) {
      stop();
      return false;
    }
  return true;
}

void FollowerRuns::stop() {
  runs_.clear();
  kind_ = Kind::None;
  key_.clear();
}

void FollowerRuns::follow(const Params& a, std::string* err) {
  for (CompareRun& r : runs_)
    if (!r.follow(a, err)) return;
}

CompareRun::Advance FollowerRuns::advance_to(double t, std::string* err, const std::function<bool()>& interrupted,
                                             std::size_t* behind) {
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    const CompareRun::Advance a = runs_[i].advance_to(t, err, interrupted);
    if (a == CompareRun::Advance::Done) continue;
    *behind = i;
    return a;
  }
  return CompareRun::Advance::Done;
}

void FollowerRuns::sample() {
  for (CompareRun& r : runs_) r.sample();
}

}  // namespace sph::detail
