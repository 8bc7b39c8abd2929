// The step with individual time steps (time.levels > 1): one sub-step of a block of power-of-two
// steps (integrators/block_steps.h), the stages evaluating only the particles whose step ends, and
// every particle's wanted dt from the stages' per-particle limits.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/pipeline.h"
#include "core/stage.h"
#include "integrators/block_steps.h"
#include "sph/world.h"

namespace sph {

void World::wanted_steps(std::vector<double>& want) {
  const std::size_t n = p_.fluid();
  want.assign(n, Stage::kNoLimit);
  const StageContext ctx = context();
  for (const auto& s : pipeline_->stages()) s->dt_limits(ctx, want);
  const auto& h = p_[Field::H];
  const double cfl = cfg_.params.time.cfl, tau = push_.active() ? push_.tau : Stage::kNoLimit;
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    double w = std::min(want[i], tau);
    if (h[i] > 0.0) {  // point masses (h = 0): their stages give the limits
      const double a = std::sqrt(p_.a[0][i] * p_.a[0][i] + p_.a[1][i] * p_.a[1][i] + p_.a[2][i] * p_.a[2][i]);
      if (a > 0.0) w = std::min(w, std::sqrt(h[i] / a));  // force condition
      const double v = p_.vel(i).norm();
      if (w == Stage::kNoLimit && v > 0.0) w = h[i] / v;  // free streaming: at most h per step
    }
    want[i] = cfl * w;
  }
}

void World::advance_block(double dt_max) {
  if (block_->synchronised() && !current_) {  // a block starts from every particle's current rates
    evaluate(t_);
    current_ = true;
  }
  // the energy guard measures from a synchronised state: the first block's start, not its end
  if (block_->synchronised() && !checks_.energy_armed())
    checks_.check_energy(cfg_, [this] { return report().diagnostics(); }, p_, step_, t_);
  const double dt_free = next_dt();
  checks_.check_dt(std::min(dt_free, dt_max), dt_free, true, p_, step_, t_);
  PhaseSpace s = phase_space();
  const double t0 = t_;
  struct Active {  // the stages see the active particles during the block's evaluations only
    World& w;
    ~Active() { w.active_ = nullptr; }
  } clear_after{*this};
  const BlockSteps::Hooks hooks{
      [this, t0](double offset) {
        active_ = block_.get();
        evaluate(t0 + offset);
        active_ = nullptr;
      },
      [this](std::vector<double>& want) { wanted_steps(want); },
      [this]() -> const NeighbourList& { return lists_.lists(pipeline_->exact_lists()); }};
  const double dt = block_->step(s, p_, hooks, dt_max);
  block_->write_levels(p_[Field::StepLevel]);
  current_ = block_->synchronised();
  rates_known_ = true;
  bound();
  t_ += dt;
  dt_last_ = dt;
  ++step_;
  checks_.check_levels(block_->take_too_long(), cfg_.params.time.levels, step_, t_);
  after_step();
  check_step();
}

}  // namespace sph
