// The step loop (seed 000 §3.5, steps 1-9): boundaries -> ghosts -> neighbours -> the scene's stages in
// pipeline order, driven by the chosen integrator.
#include "sph/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <omp.h>

#include "core/parallel.h"
#include "core/pipeline.h"
#include "core/stage.h"
#include "core/stages.h"
#include "core/team_size.h"
#include "integrators/block_steps.h"
#include "integrators/landing_step.h"

namespace sph {
namespace {

/// Steps between two spatial reorderings of the particle arrays: particles move less than about
/// 16 × 0.3 h in that time (the CFL factor keeps a step's displacement below 0.3 h), so neighbours stay
/// within a few cache lines of each other; a reordering (a sort of N keys, a copy of each field) costs
/// far less than a step.
constexpr std::int64_t kReorderEvery = 16;

/// Seconds since `t0` on the monotonic clock.
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

World::World(const RunConfig& cfg)
    : cfg_(cfg), kernel_(cfg.params.kernel.type, cfg.scene->dim), stats_(std::make_unique<EvalStats>()),
      team_(std::make_unique<TeamChooser>()) {
  check_physics(*cfg_.scene, cfg_.params.physics);
  if (const std::string why = block_steps_refusal(cfg_.params); !why.empty()) throw ConfigError(why);
  pipeline_ = std::make_unique<Pipeline>(cfg_.params, cfg_.scene->dim);
  SceneSetup setup = cfg_.scene->build(cfg_.params, cfg_.values);
  p_ = std::move(setup.particles);
  p_.partition_by_kind();
  if (p_.fluid() == 0)  // e.g. a tank narrower than a particle spacing: nothing would move or be measured
    throw ConfigError("the scene's values place no fluid particle (only " + std::to_string(p_.size()) +
                      " wall particles): widen the fluid or lower its spacing");
  p_.add_fields(pipeline_->fields());
  if (cfg_.params.time.levels > 1) p_.add_fields({Field::StepLevel});
  domain_ = setup.domain;
  spacing_ = setup.spacing;
  wall_strength_ = setup.wall_strength;
  start_shared_ = FieldSet{}.add(Field::Mass).add(Field::H);
  for (const EvolvedPair& e : pipeline_->evolved()) start_shared_.add(e.first);
  integrator_ = make_integrator(cfg_.params.time.integrator);
  if (cfg_.params.time.levels > 1) block_ = std::make_unique<BlockSteps>(cfg_.params.time.levels);
  if (cfg_.scene->reference) {
    reference_ = cfg_.scene->reference(cfg_.params, cfg_.values);
    if (reference_) ref_columns_ = reference_->columns();
  }
  bound();
  evaluate();
  if (cfg_.scene->density_anchor && p_.has(Field::Density)) {
    const auto [k, rho_target] = cfg_.scene->density_anchor(cfg_.values);
    const double scale = rho_target / p_[Field::Density][k];
    for (std::size_t i = 0; i < p_.size(); ++i) p_[Field::Mass][i] *= scale;
    evaluate();
  }
  if (cfg_.scene->initial_pressure && p_.has(Field::Energy) && p_.has(Field::Density)) {
    auto& u = p_[Field::Energy];
    const auto& rho = p_[Field::Density];
    for (std::size_t i = 0; i < p_.size(); ++i)
      u[i] = cfg_.scene->initial_pressure(p_.pos(i), cfg_.values) / ((cfg_.params.gas.gamma - 1.0) * rho[i]);
    evaluate();
  }
  // the start must be a state the h solve reaches (seed 000 eq. 3.5.1): otherwise nothing runs or is written
  const std::size_t failed = stats_->density.not_converged;
  if (failed > 0 && p_.has(Field::Density) && cfg_.params.physics.smoothing == HMode::Variable)
    throw DivergedError(stats_->density.first_not_converged, 0, 0.0, "h",
                        "the smoothing-length solve did not converge for " + std::to_string(failed) + " of " +
                            std::to_string(p_.fluid()) + " particles at the start (the first is particle " +
                            std::to_string(stats_->density.first_not_converged) + "; kernel.eta = " +
                            std::to_string(eta()) + "): change kernel.eta, or raise h.max_iter");
  current_ = true;
  reorder();
  checks_.forget_crossings();  // storage indices changed; a start is placed inside its walls
  RunChecks::check_finite(p_, step_, t_);
  checks_.check_pericentres(cfg_, p_);
  checks_.check_assumptions(cfg_);
}

World::~World() = default;

void World::set_params(const Params& p) {
  const Params old = cfg_.params;
  if (const std::string why = block_steps_refusal(p); !why.empty()) throw ConfigError(why);
  if (p.physics != old.physics || gravity_grad_h(p) != gravity_grad_h(old)) {
    check_physics(*cfg_.scene, p.physics);  // throws before anything changes
    pipeline_ = std::make_unique<Pipeline>(p, p_.dim());
    p_.add_fields(pipeline_->fields());
    start_shared_ = FieldSet{}.add(Field::Mass).add(Field::H);
    for (const EvolvedPair& e : pipeline_->evolved()) start_shared_.add(e.first);
    integrator_->reset();
    reset_timings();
  }
  cfg_.params = p;
  if (p.kernel.type != old.kernel.type) kernel_ = Kernel(p.kernel.type, p_.dim());
  if (p.time.integrator != old.time.integrator) integrator_ = make_integrator(p.time.integrator);
  // a block of individual steps ends where it stands: the next step starts one from the new rates
  if (p.time.levels != old.time.levels) block_ = p.time.levels > 1 ? std::make_unique<BlockSteps>(p.time.levels) : nullptr;
  if (block_) p_.add_fields({Field::StepLevel});
  if (block_) block_->synchronise();
  current_ = false;  // rates depend on the parameters: re-evaluate before the next step
  rates_known_ = false;
  lists_.invalidate();  // the kernel, h or the boundaries may have changed
  t_last_eval_ = -1.0;  // rates of other parameters make no first guess
  // new parameters may change dt and the energies legitimately (e.g. gravity switched on): the blow-up
  // guards measure from the next step on
  checks_.restart_guards();
  checks_.check_assumptions(cfg_);
}

void World::set_push(const Push& push) {
  const Push next = push.active() ? push : Push{};
  if (next == push_) return;
  push_ = next;
  pushes_.push_back(PushEvent{step_, push_});
  current_ = false;  // the rates of the current state change with the push
  checks_.restart_guards();
}

PhaseSpace World::phase_space() {
  PhaseSpace s;
  s.dim = p_.dim();
  s.n = p_.fluid();  // wall particles do not move
  for (int k = 0; k < 3; ++k) { s.x[k] = &p_.x[k]; s.v[k] = &p_.v[k]; s.a[k] = &p_.a[k]; }
  if (pipeline_->drifts())
    for (int k = 0; k < 3; ++k) s.drift[k] = &p_[component(Field::XsphX, k)];
  for (const EvolvedPair& e : pipeline_->evolved()) s.evolved.push_back({&p_[e.first], &p_[e.second]});
  return s;
}

void World::step(double dt_max) {
  const int full = omp_get_max_threads();
  last_team_ = adaptive_threads_ ? team_->next(full) : full;
  struct Team {  // the caller's setting comes back however the step ends
    int full;
    ~Team() { omp_set_num_threads(full); }
  } restore{full};
  omp_set_num_threads(last_team_);
  const auto t0 = std::chrono::steady_clock::now();
  advance(dt_max);
  if (adaptive_threads_) team_->record(since(t0));
}

void World::advance(double dt_max) {
  if (step_ > 0 && step_ % kReorderEvery == 0) reorder();
  if (block_) return advance_block(dt_max);
  if (pipeline_->projector()) return advance_projected(dt_max);
  const double dt = step_length(dt_max);
  PhaseSpace s = phase_space();
  const double t0 = t_;
  current_ = integrator_->step(s, [this, t0](double offset) { evaluate(t0 + offset); }, dt, current_);
  end_step(dt);
}

double World::step_length(double dt_max) {
  const double dt_free = next_dt();
  const double dt = landing_step(dt_free, dt_max);
  checks_.check_dt(dt, dt_free, cfg_.params.time.dt <= 0.0, p_, step_, t_);
  return dt;
}

void World::end_step(double dt) {
  bound();
  t_ += dt;
  dt_last_ = dt;
  ++step_;
  after_step();
  check_step();
}

void World::check_step() {
  RunChecks::check_finite(p_, step_, t_);
  checks_.check_walls(p_, cfg_.params, step_, t_);
  checks_.check_domain(p_, domain_, step_, t_);
  checks_.check_h_solve(stats_->density, step_, t_);
  // inside a block of individual steps the state is part predicted: its energy is checked at the block's end
  if (!block_ || block_->synchronised())
    checks_.check_energy(cfg_, [this] { return report().diagnostics(); }, p_, step_, t_);
  checks_.check_reference(reference_.get(), step_, t_);
}

void World::check_output() {
  if (cfg_.params.physics.gravity != GravityType::None)
    checks_.check_energy(cfg_, [this] { return report().diagnostics(); }, p_, step_, t_, true);
  if (reference_ && !cfg_.scene->error_bounds.empty()) check_error_bounds(report().reference_values());
}

void World::check_error_bounds(const std::vector<double>& values) {
  checks_.check_error_bounds(cfg_, reference_.get(), ref_columns_, values, step_, t_);
}

void World::bound() { checks_.tally(apply_boundaries(domain_, p_)); }

Report World::report() const {
  return Report(Report::Inputs{cfg_, kernel_, p_, by_id_, domain_, *pipeline_, *stats_, lists_, reference_.get(),
                               ref_columns_, timings_, push_, eta(), spacing_, wall_strength_, since_, t_, dt_last_,
                               step_, evaluations_, updates_});
}

void World::after_step() {
  bool due = false;
  for (const auto& s : pipeline_->stages()) due = due || s->acts_after(cfg_.params, step_);
  if (!due) return;
  prepare_neighbours();  // for the state the step ended in
  lists_.every_list();   // an action may visit every particle
  StageContext ctx = context();
  for (const auto& s : pipeline_->stages())
    if (s->acts_after(cfg_.params, step_)) {
      s->after_step(ctx);
      copy_ghost_fields(p_, s->shares());
    }
  lists_.rewrap(p_);
  for (const auto& s : pipeline_->stages()) {
    Particles fresh;
    if (s->acts_after(cfg_.params, step_) && s->take_resampled(fresh)) adopt(std::move(fresh));
  }
  current_ = false;  // the state changed: the next step evaluates first
}

bool World::advance_to(double t_target, const std::function<bool()>& interrupted) {
  while (t_ < t_target * (1.0 - 1e-14) - 1e-300) {
    if (interrupted && interrupted()) return false;
    step(t_target - t_);  // the steps of `sph run` towards its output times (integrators/landing_step.h)
    if (t_ > t_target) t_ = t_target;
  }
  // A target within the loop's tolerance (1e-14 relative; e.g. run A's sliver of a last step onto t_end)
  // is landed on without a step, so that run B shows exactly run A's time (the soak test saw them differ
  // in the last digits).
  if (t_ < t_target) t_ = t_target;
  return true;
}

}  // namespace sph
