#include "compare_run.h"

#include <cstdio>

namespace sph::detail {

bool CompareRun::start(const RunConfig& a, const std::vector<std::string>& overrides, std::string* err,
                       const std::string* state, const std::string& name) {
  stop();
  name_ = name;
  try {
    if (state)  // a scene value builds other particles, which a loaded state replaces
      for (const std::string& o : overrides)
        if (o.rfind("scene.", 0) == 0)
          throw ConfigError("its override " + o + " changes the initial particles, which the loaded state replaces");
    world_ = std::make_unique<World>(fork_config(a, overrides));
    if (state) world_->restore_state(*state, "the loaded state, for run B");
  } catch (const std::exception& e) {
    world_.reset();
    std::string list;
    for (const std::string& o : overrides) list += (list.empty() ? "" : ", ") + o;
    *err = name + " (" + list + ") cannot be built: " + e.what();
    return false;
  }
  overrides_ = overrides;
  return true;
}

void CompareRun::stop() {
  world_.reset();
  overrides_.clear();
  history_.clear();
}

bool CompareRun::follow(const Params& a, std::string* err) {
  if (!world_) return true;
  try {
    RunConfig cfg = world_->config();
    cfg.params = a;
    world_->set_params(fork_config(cfg, overrides_).params);
    return true;
  } catch (const std::exception& e) {
    *err = label() + " keeps its parameters: " + e.what();
    return false;
  }
}

CompareRun::Advance CompareRun::advance_to(double t, std::string* err, const std::function<bool()>& interrupted) {
  if (!world_) return Advance::Done;
  try {
    return world_->advance_to(t, interrupted) ? Advance::Done : Advance::Behind;
  } catch (const std::exception& e) {
    *err = label() + ": " + e.what();
    return Advance::Failed;
  }
}

std::string CompareRun::label() const {
  std::string list;
  for (const std::string& o : overrides_) list += (list.empty() ? "" : ", ") + o;
  return name_ + " (" + list + ")";
}

std::string CompareRun::too_slow(double t, double budget) const {
  char what[200];
  std::snprintf(what, sizeof what,
                "it needed more than %g s to follow one step of run A (B at t = %.6g, A at %.6g; B's last time step "
                "%.3g): the comparison stopped",
                budget, world_->time(), t, world_->report().diagnostics().dt);
  return label() + " cannot keep up: " + what;
}

void CompareRun::sample() {
  if (world_) history_.add(history_sample(*world_));
}

void CompareRun::fill(CompareFrame& f) const {
  f.overrides = overrides_;
  f.snapshot = world_->report().snapshot();
  f.diagnostics = world_->report().diagnostics();
  f.ref_values = world_->report().reference_values();
  f.history = history_.samples();
  f.warnings = world_->checks().warnings();
  f.config = world_->config();
}

}  // namespace sph::detail
