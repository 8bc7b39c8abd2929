// Publishing a frame of the engine thread (stepper/engine_loop.h): the World's snapshot, diagnostics,
// reference, history, comparison and inspection copied into the triple buffer's back frame.
#include "engine_loop.h"

namespace sph::detail {

void EngineLoop::publish(int record_index) {
  StepperFrame& f = out_.back();
  f.serial = ++serial_;
  f.world_serial = world_serial_;
  if (world_) {
    f.snapshot = world_->report().snapshot();
    trails_.decorate(f.snapshot);
    if (tree_probe_ >= 0) {
      f.snapshot.tree_cells = world_->report().tree_cells(static_cast<std::size_t>(tree_probe_));
      if (!f.snapshot.tree_cells.empty()) f.snapshot.tree_probe = tree_probe_;
    }
    f.diagnostics = world_->report().diagnostics();
    f.has_reference = world_->report().has_reference();
    f.ref_columns = world_->report().reference_columns();
    f.ref_values = world_->report().reference_values();
    world_->check_error_bounds(f.ref_values);  // the live view is the GUI's output: its warnings go on the status line
    f.ref_primary = world_->report().reference() ? world_->report().reference()->primary() : -1;
    f.ref_series = world_->report().reference() ? world_->report().reference()->series() : std::vector<std::pair<int, int>>{};
    f.stages = world_->report().stage_names();
    f.density = world_->report().density_stats();
    f.warnings = world_->checks().warnings();
    f.config = world_->config();
    f.push = world_->push();
    f.pushes = world_->pushes();
  } else {
    f.snapshot = Snapshot{};
    f.diagnostics = Diagnostics{};
    f.has_reference = false;
    f.ref_columns.clear();
    f.ref_values.clear();
    f.ref_primary = -1;
    f.ref_series.clear();
    f.stages.clear();
    f.density = DensityStats{};
    f.warnings.clear();
    f.config = cfg_;
    f.push = Push{};
    f.pushes.clear();
  }
  f.params_version = adopted_;
  f.history = history_.samples();
  f.running = stepping() && running_;
  f.at_end = at_end_;
  f.real_time_factor = rtf_;
  f.steps_per_second = meter_.rate();
  f.particle_steps_per_second = meter_.rate() * static_cast<double>(f.snapshot.count);
  f.diverged = diverged_;
  f.diverged_particle = diverged_particle_;
  f.diverged_step = diverged_step_;
  f.error = error_;
  f.notice = notice_;
  f.record_every = record_every_;
  f.record_index = record_index;
  const bool run = stepping() && running_;
  f.inspection = inspect_.refresh(world_.get(), world_serial_, adopted_, run);
  f.comparing = followers_.kind() == FollowerRuns::Kind::Compare;
  if (f.comparing) {
    followers_.run(0).fill(f.compare);
    f.compare.inspection = inspect_b_.refresh(followers_.run(0).world(), world_serial_, adopted_, run);
  } else {
    f.compare = CompareFrame{};
  }
  const bool sweeping = followers_.kind() == FollowerRuns::Kind::Sweep;
  f.sweep_key = sweeping ? followers_.sweep_key() : std::string();
  f.sweep.resize(sweeping ? followers_.size() : 0);
  for (std::size_t i = 0; i < f.sweep.size(); ++i) followers_.run(i).fill(f.sweep[i]);
  out_.publish();
  published_.store(serial_, std::memory_order_release);
  last_publish_ = Clock::now();
}

}  // namespace sph::detail
