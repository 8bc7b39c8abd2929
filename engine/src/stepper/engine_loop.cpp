// The engine thread's loop (stepper/engine_loop.h): drains the inbox, applies commands, adopts posted
// params and rebuilds the World; stepping is in engine_loop_step.cpp, publishing in engine_loop_publish.cpp.
#include "engine_loop.h"
#include "text/number_text.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <thread>

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#endif

namespace sph::detail {
namespace {

constexpr double kMaxLag = 0.25;  ///< real-time pacing forgets a backlog longer than this [s]

std::string format(double v) { return exact_text(v); }

/// Lower this thread's priority (Linux threads have their own nice value; the OpenMP team the thread
/// creates later inherits it). Failure is harmless: the engine just competes equally with the display.
void lower_priority([[maybe_unused]] int nice) {
#ifdef __linux__
  if (nice <= 0) return;
  const id_t tid = static_cast<id_t>(::gettid());
  errno = 0;
  const int current = ::getpriority(PRIO_PROCESS, tid);
  if (errno == 0) (void)::setpriority(PRIO_PROCESS, tid, std::min(19, current + nice));
#endif
}

}  // namespace

void EngineLoop::run() {
  if (options_.threads > 0) omp_set_num_threads(options_.threads);
  lower_priority(options_.nice);
  for (;;) {
    if (record_held_) {  // a recording frame must reach the reader before anything replaces it
      if (out_.unread()) {
        if (inbox_.stop_requested()) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      record_held_ = false;
    }
    const InboxBatch batch = inbox_.take(adopted_);
    if (batch.stop) return;
    for (const Command& c : batch.commands) apply(c);
    if (batch.has_params) adopt(batch);
    if (!batch.commands.empty() || batch.has_params) {
      publish(emit_record_);
      record_held_ = emit_record_ >= 0;
      emit_record_ = -1;
      continue;  // take whatever arrived meanwhile before stepping
    }
    if (!stepping()) {
      inbox_.wait();
      continue;
    }
    if (rtf_ > 0.0 && single_steps_ == 0) {  // real-time factor: simulated time follows the wall clock
      const auto due = pace_wall_ + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>((world_->time() - pace_t_) / rtf_));
      const auto now = Clock::now();
      if (now < due) {
        inbox_.wait_until(due);
        continue;
      }
      if (now - due > std::chrono::duration<double>(kMaxLag)) anchor_pacing();  // too slow: no catching up
    }
    step();
  }
}

void EngineLoop::apply(const Command& c) {
  using K = Command::Kind;
  switch (c.kind) {
    case K::Reset: {
      if (cfg_.scene == nullptr) { error_ = "reset: no scene is loaded"; break; }
      RunConfig nc = cfg_;
      nc.params = c.config.params;
      rebuild(nc);
      adopted_ = std::max(adopted_, c.params_version);
      break;
    }
    case K::Load:
      rebuild(c.config);
      adopted_ = std::max(adopted_, c.params_version);  // a failed load's params are dropped too
      break;
    case K::Pause:
      running_ = false;
      single_steps_ = 0;
      meter_.zero();
      break;
    case K::Resume:
      // at t_end with "stop at t_end" on, there is nothing to run to: stay there (raise t_end or turn
      // the stop off to run on)
      if (world_ && at_end_ && stop_at_end_ && reached(world_->time(), world_->params().time.t_end)) break;
      if (world_ && !diverged_) {
        running_ = true;
        at_end_ = false;
        anchor_pacing();
        meter_.restart();
      }
      break;
    case K::StepOnce:
      running_ = false;
      // as Resume: at t_end with "stop at t_end" on, a step would leave t_end (steps queued before the end
      // was reached arrive here after it)
      if (world_ && at_end_ && stop_at_end_ && reached(world_->time(), world_->params().time.t_end)) break;
      if (world_ && !diverged_) ++single_steps_;
      break;
    case K::SetSceneValue:
      set_scene_value(c.name, c.value);
      break;
    case K::SetRealTimeFactor:
      rtf_ = std::isfinite(c.value) ? std::max(0.0, c.value) : 0.0;
      anchor_pacing();
      break;
    case K::SetStopAtEnd:
      stop_at_end_ = c.flag;
      break;
    case K::SetPauseAt:
      pause_at_ = std::isfinite(c.value) && c.value > 0.0 ? c.value : 0.0;
      break;
    case K::SetRecordInterval:
      start_recording(c.value);
      break;
    case K::SetTreeProbe:
      tree_probe_ = std::isfinite(c.value) && c.value >= 0.0 ? static_cast<std::int64_t>(c.value) : -1;
      break;
    case K::SetCompare:
      start_compare(c.names);
      break;
    case K::SetSweep:
      start_sweep(c.name, c.names);
      break;
    case K::SaveState:
      save_state(c.name);
      break;
    case K::LoadState:
      rebuild(c.config, &c.state, c.name);
      adopted_ = std::max(adopted_, c.params_version);
      break;
    case K::SetInspect:
      inspect_.set_id(std::isfinite(c.value) && c.value >= 0.0 ? static_cast<std::int64_t>(c.value) : -1);
      inspect_b_.set_id(inspect_.id());
      break;
    case K::SetPush:
      if (world_) world_->set_push(c.push);  // run A only: the comparison's run B is not pushed
      break;
  }
}

void EngineLoop::set_scene_value(const std::string& name, double value) {
  if (cfg_.scene == nullptr) {
    error_ = "no scene is loaded";
    return;
  }
  RunConfig nc = cfg_;
  if (world_) nc.params = world_->params();
  try {
    nc.set("scene." + name, format(value), "scene value");
  } catch (const std::exception& e) {
    error_ = e.what();
    return;
  }
  rebuild(nc);
}

void EngineLoop::adopt(const InboxBatch& b) {
  if (b.params_version <= adopted_) return;  // superseded by a reset or load carrying newer params
  try {
    if (world_) world_->set_params(b.params);
    else cfg_.params = b.params;
    if (world_) followers_.follow(world_->params(), &error_);
  } catch (const std::exception& e) {  // a physics the scene cannot run: keep the old params, say why
    error_ = e.what();
  }
  adopted_ = b.params_version;
  anchor_pacing();
}

void EngineLoop::rebuild(const RunConfig& cfg, const std::string* state, const std::string& from) {
  try {
    if (cfg.scene == nullptr) throw ConfigError("no scene given");
    auto w = std::make_unique<World>(cfg);
    if (state) {
      w->restore_state(*state, "checkpoint " + from);
      notice_ = "loaded state from " + from + " (t = " + format(w->time()) + ")";
    }
    world_ = std::move(w);
    cfg_ = world_->config();
    ++world_serial_;
    history_.clear();
    trails_.clear();
    trails_.record(*world_);
    error_.clear();
    // run B restarts beside A: from t = 0, or from the same loaded state (B at A's time)
    if (followers_.on() && !followers_.restart(cfg_, &error_, state))
      error_ += followers_.kind() == FollowerRuns::Kind::Sweep ? " (the sweep stopped)" : " (the comparison stopped)";
    sample_history();
    if (at_end_) running_ = true;  // the run had only stopped at t_end: run the new World
    diverged_ = at_end_ = false;
    if (stop_at_end_ && reached(world_->time(), world_->params().time.t_end)) {
      at_end_ = true;  // a state saved at (or past) t_end: stopped there, not run on past it
      running_ = false;
    }
    diverged_particle_ = diverged_step_ = -1;
    meter_.zero();
    anchor_pacing();
    if (record_every_ > 0.0) start_recording(record_every_);  // the new World's frames start at its t
    if (state) check_loaded_state();
  } catch (const std::exception& e) {
    error_ = "could not build scene '" + (cfg.scene ? cfg.scene->name : std::string("?")) + "': " + e.what();
    if (!world_) {
      cfg_ = cfg;
      running_ = false;
    }
  }
}

void EngineLoop::check_loaded_state() {
  // a state saved from a diverged run (the divergence dialog offers that) is shown as diverged at once
  try {
    RunChecks::check_finite(world_->particles(), world_->steps(), world_->time());
  } catch (const DivergedError& e) {
    diverged_particle_ = e.particle;
    diverged_step_ = e.step;
    error_ = std::string("the loaded state: ") + e.what();
    diverged_ = true;
    running_ = false;
    single_steps_ = 0;
  }
}

bool EngineLoop::restart_a() {
  followers_.stop();
  RunConfig a = cfg_;
  a.params = world_->params();
  rebuild(a);
  return world_ != nullptr;
}

bool EngineLoop::can_follow(const char* what, const std::vector<std::vector<std::string>>& runs) {
  if (!world_) {
    error_ = std::string(what) + ": no scene is loaded";
    return false;
  }
  RunConfig a = cfg_;
  a.params = world_->params();
  try {
    for (const std::vector<std::string>& overrides : runs) (void)fork_config(a, overrides);
  } catch (const std::exception& e) {
    error_ = std::string(what) + ": " + e.what();
    return false;
  }
  return true;
}

void EngineLoop::start_compare(const std::vector<std::string>& overrides) {
  if (overrides.empty()) {
    if (followers_.kind() == FollowerRuns::Kind::Compare) followers_.stop();
    return;
  }
  // A restarts from t = 0 and B beside it
  if (can_follow("compare", {overrides}) && restart_a() && followers_.start_compare(world_->config(), overrides, &error_))
    followers_.sample();
}

void EngineLoop::start_sweep(const std::string& key, const std::vector<std::string>& values) {
  if (values.empty()) {
    if (followers_.kind() == FollowerRuns::Kind::Sweep) followers_.stop();
    return;
  }
  std::vector<std::vector<std::string>> runs;
  for (const std::string& v : values) runs.push_back({key + "=" + v});
  if (can_follow("sweep", runs) && restart_a() && followers_.start_sweep(world_->config(), key, values, &error_))
    followers_.sample();
}

}  // namespace sph::detail
