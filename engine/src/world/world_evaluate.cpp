// One evaluation of the rates: boundaries, ghosts and neighbour lists (kept while they fit), then the
// scene's stages in pipeline order, timed; and the timestep the rates allow.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/parallel.h"
#include "core/pipeline.h"
#include "core/stage.h"
#include "integrators/block_steps.h"
#include "sph/world.h"

namespace sph {
namespace {

/// Seconds since `t0` on the monotonic clock.
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

double World::eta() const { return cfg_.params.kernel.eta > 0.0 ? cfg_.params.kernel.eta : kernel_.default_eta(); }

void World::reset_timings() {
  timings_.assign(1, StageTiming{"neighbours", 0.0, 0});
  for (const auto& s : pipeline_->stages()) timings_.push_back(StageTiming{std::string(s->name()), 0.0, 0});
}

StageContext World::context() const {
  // Stages get the particles mutable; const callers (potentials, limits) only read them.
  const NeighbourList& lists = lists_.lists(pipeline_->exact_lists());
  return StageContext{cfg_.params, kernel_, domain_, const_cast<Particles&>(p_), lists, lists_.h_limit(),
                      eta(), spacing_, wall_strength_, *stats_, since_,
                      active_ ? &active_->active() : nullptr, active_ ? &active_->summed() : nullptr};
}

void World::prepare_neighbours() {
  const ListRequest rq{domain_, kernel_, cfg_.params.physics.smoothing, start_shared_, pipeline_->exact_lists(),
                       t_last_eval_ >= 0.0, since_, dt_last_, block_ != nullptr && pipeline_->lists_by_rows()};
  try {
    lists_.prepare(p_, rq);
  } catch (const GhostOverflow& e) {
    throw DivergedError(-1, step_, t_, "h", e.what());
  }
}

void World::evaluate(double t_eval) {
  since_ = t_last_eval_ >= 0.0 && t_eval >= t_last_eval_ ? t_eval - t_last_eval_ : 0.0;
  bound();
  const std::size_t n = p_.size();
  StageContext ctx = context();
  if (timings_.size() != pipeline_->stages().size() + 1) reset_timings();
  struct Rewrap {  // the wrapped coordinates come back however the stages end
    World& w;
    ~Rewrap() { w.lists_.rewrap(w.p_); }
  } rewrap_after{*this};
  for (int attempt = 0;; ++attempt) {
    auto t0 = std::chrono::steady_clock::now();
    if (pipeline_->uses_neighbours()) prepare_neighbours();  // pure N-body: no lists at all
    if (active_) {  // the lists of the active particles, then of those whose density they read
      lists_.need(active_->active());
      active_->mark_summed(p_, lists_.lists(pipeline_->exact_lists()));
      lists_.need(active_->summed());
    } else {
      lists_.every_list();
    }
    timings_[0].seconds += since(t0);
    ++timings_[0].calls;
    if (!pipeline_->sets_acceleration())
      for (int k = 0; k < 3; ++k) std::fill(p_.a[k].begin(), p_.a[k].begin() + static_cast<std::ptrdiff_t>(n), 0.0);
    bool complete = true;
    std::size_t k = 1;
    for (const auto& stage : pipeline_->stages()) {
      t0 = std::chrono::steady_clock::now();
      const bool done = stage->run(ctx);
      if (done) copy_ghost_fields(p_, stage->shares());
      timings_[k].seconds += since(t0);
      ++timings_[k++].calls;
      if (!done) { complete = false; break; }
    }
    lists_.rewrap(p_);
    if (complete) {
      add_push_acceleration(push_, domain_, p_);  // a body force of its own, after the stages' accelerations
      break;
    }
    lists_.overflowed();  // an h outgrew its list: new lists from the new h
    if (attempt > 20)
      throw DivergedError(-1, step_, t_, "h", "the smoothing length outgrows its neighbour lists on every rebuild");
  }
  ++evaluations_;
  updates_ += static_cast<std::int64_t>(active_ ? active_->active().size() : p_.fluid());
  t_last_eval_ = t_eval;
  rates_known_ = true;
}

double World::next_dt() {
  if (cfg_.params.time.dt > 0.0) return cfg_.params.time.dt;
  // The last evaluation's rates set dt (for RK4 and the predictor-corrector that is a stage within the
  // last step): evaluating again just for dt would double their cost.
  if (!rates_known_) { evaluate(); current_ = true; }
  if (block_) {  // individual time steps: to the next end of a particle's step, or a new block's length
    if (!block_->synchronised()) return block_->next_dt();
    std::vector<double> want;
    wanted_steps(want);
    return block_->block_length(want);
  }
  const StageContext ctx = context();
  double dt = Stage::kNoLimit;
  for (const auto& s : pipeline_->stages()) dt = std::min(dt, s->dt_limit(ctx));
  const std::size_t n = p_.fluid();
  const auto& h = p_[Field::H];
  double dt_force = Stage::kNoLimit, dt_move = Stage::kNoLimit;  // minima: the same for any thread count
#pragma omp parallel for reduction(min : dt_force, dt_move) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::sqrt(p_.a[0][i] * p_.a[0][i] + p_.a[1][i] * p_.a[1][i] + p_.a[2][i] * p_.a[2][i]);
    if (h[i] <= 0.0) continue;  // point masses (N-body): their stages give the limits
    if (a > 0.0) dt_force = std::min(dt_force, std::sqrt(h[i] / a));  // force condition
    const double v = p_.vel(i).norm();
    if (v > 0.0) dt_move = std::min(dt_move, h[i] / v);
  }
  dt = std::min(dt, dt_force);
  if (push_.active()) dt = std::min(dt, push_.tau);  // relaxation towards v_push, resolved in time
  // Without forces or signal speeds (free streaming), no particle moves more than h in a step.
  if (dt == Stage::kNoLimit) dt = dt_move;
  return cfg_.params.time.cfl * dt;
}

}  // namespace sph
