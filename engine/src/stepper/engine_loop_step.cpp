// Stepping the engine thread's World (stepper/engine_loop.h): one World::step with its bookkeeping
// (divergence, t_end, recording frames, when to publish), recording intervals, history and pacing anchor.
#include "engine_loop.h"

#include <algorithm>
#include <cmath>

namespace sph::detail {
namespace {

constexpr double kStaleAfter = 0.25;  ///< publish even if the last frame is unread after this long [s]

}  // namespace

void EngineLoop::step() {
  const double t = world_->time();
  const double t_end = world_->params().time.t_end;
  const bool end_ahead = stop_at_end_ && !reached(t, t_end);
  // a pause time ahead (a lesson's "pause_at"): the step lands on it, and the run pauses there
  const bool pause_ahead = pause_at_ > 0.0 && !reached(t, pause_at_);
  double dt_max = end_ahead ? t_end - t : 1e300;
  if (pause_ahead) dt_max = std::min(dt_max, pause_at_ - t);
  try {
    // Frames land exactly on t0 + k every when they are at least a step apart; with steps longer than
    // the interval, shortening every step to it cost the run its speed (box_perturbed: 9.8 steps/s), so
    // the frame is then the first step at or past its time. (next_dt may evaluate the rates, which can
    // diverge: inside the try. The soak test found it outside, where a divergence ended the program.)
    if (record_every_ > 0.0 && record_every_ >= world_->next_dt())
      dt_max = std::min(dt_max, record_t0_ + record_next_ * record_every_ - t);
    world_->step(dt_max);
  } catch (const DivergedError& e) {
    diverged_particle_ = e.particle;
    diverged_step_ = e.step;
    error_ = e.what();
    diverged_ = true;
  } catch (const std::exception& e) {  // anything else: stop the same way, the message says what
    error_ = std::string("step failed: ") + e.what();
    diverged_ = true;
  }
  if (!diverged_ && followers_.on() && !follow()) return;
  if (diverged_) {
    running_ = false;
    single_steps_ = 0;
    meter_.zero();
    publish();
    return;
  }
  meter_.tick();
  trails_.record(*world_);
  if (history_.due(world_->steps())) sample_history();

  bool force = false;
  if (single_steps_ > 0) {
    --single_steps_;
    force = true;
  }
  int record = -1;
  // the latest frame time reached (a long step may pass several)
  while (record_every_ > 0.0 && reached(world_->time(), record_t0_ + record_next_ * record_every_)) record = record_next_++;
  if (pause_ahead && reached(world_->time(), pause_at_)) {
    running_ = false;
    single_steps_ = 0;
    force = true;
  }
  if (end_ahead && reached(world_->time(), t_end)) {
    running_ = false;
    at_end_ = true;
    single_steps_ = 0;
    force = true;
  }
  const double since = std::chrono::duration<double>(Clock::now() - last_publish_).count();
  if (record >= 0) {
    publish(record);
    record_held_ = true;
  } else if (force || (since >= options_.publish_interval && (!out_.unread() || since >= kStaleAfter))) {
    publish();
  }
}

bool EngineLoop::follow() {
  // Run B (or a sweep's runs) to A's time. A B whose dt collapses crawled on inside this call, deaf to
  // every command, and the program could not quit (the soak test hung in ~Stepper on one): a stop
  // interrupts it, and a B that needs longer than the budget for one step of A ends the comparison,
  // saying so. Other commands wait for B, so that every frame shows both runs at one time.
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(options_.compare_budget));
  const auto enough = [&] { return inbox_.stop_requested() || Clock::now() > until; };
  std::size_t behind = 0;
  switch (followers_.advance_to(world_->time(), &error_, enough, &behind)) {
    case CompareRun::Advance::Done: break;
    case CompareRun::Advance::Failed: diverged_ = true; break;
    case CompareRun::Advance::Behind:
      if (inbox_.stop_requested()) return false;  // stopping: nothing more is published
      error_ = followers_.run(behind).too_slow(world_->time(), options_.compare_budget);
      followers_.stop();  // A goes on alone
      break;
  }
  return true;
}

void EngineLoop::start_recording(double every) {
  record_every_ = (every > 0.0 && std::isfinite(every)) ? every : 0.0;
  if (record_every_ > 0.0 && world_) {
    record_t0_ = world_->time();
    record_next_ = 1;
    emit_record_ = 0;  // the current state is frame 0
  }
}

void EngineLoop::sample_history() {
  history_.add(history_sample(*world_));
  followers_.sample();  // at the same time: every history decimates alike
}

void EngineLoop::anchor_pacing() {
  pace_wall_ = Clock::now();
  pace_t_ = world_ ? world_->time() : 0.0;
}

}  // namespace sph::detail
