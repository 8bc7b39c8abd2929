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
#include "core/spatial_order.h"
#include "core/stage.h"
#include "core/team_size.h"

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

DivergedError::DivergedError(std::int64_t particle_, std::int64_t step_, double t_, const std::string& field_)
    : std::runtime_error(particle_ >= 0 ? "simulation diverged: particle " + std::to_string(particle_) +
                                              " has a non-finite " + field_ + " at step " + std::to_string(step_) +
                                              " (t = " + std::to_string(t_) + ")"
                                        : "simulation diverged: " + field_ + " at step " + std::to_string(step_) +
                                              " (t = " + std::to_string(t_) + ")"),
      particle(particle_), step(step_), t(t_), field(field_) {}

DivergedError::DivergedError(std::int64_t particle_, std::int64_t step_, double t_, const std::string& field_,
                             const std::string& reason)
    : std::runtime_error("simulation diverged: " + reason + " at step " + std::to_string(step_) +
                         " (t = " + std::to_string(t_) + ")"),
      particle(particle_), step(step_), t(t_), field(field_) {}

World::World(const RunConfig& cfg)
    : cfg_(cfg), kernel_(cfg.params.kernel.type, cfg.scene->dim), stats_(std::make_unique<EvalStats>()),
      team_(std::make_unique<TeamChooser>()) {
  check_physics(*cfg_.scene, cfg_.params.physics);
  pipeline_ = std::make_unique<Pipeline>(cfg_.params.physics, cfg_.scene->dim);
  SceneSetup setup = cfg_.scene->build(cfg_.params, cfg_.values);
  p_ = std::move(setup.particles);
  p_.partition_by_kind();
  p_.add_fields(pipeline_->fields());
  domain_ = setup.domain;
  spacing_ = setup.spacing;
  wall_strength_ = setup.wall_strength;
  start_shared_ = FieldSet{}.add(Field::Mass).add(Field::H);
  for (const EvolvedPair& e : pipeline_->evolved()) start_shared_.add(e.first);
  integrator_ = make_integrator(cfg_.params.time.integrator);
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
  crossings_ = WallCrossings{};  // storage indices changed; a start is placed inside its walls
  check_finite();
}

World::~World() = default;

double World::eta() const { return cfg_.params.kernel.eta > 0.0 ? cfg_.params.kernel.eta : kernel_.default_eta(); }
const DensityStats& World::density_stats() const { return stats_->density; }
std::size_t World::correction_fallbacks() const { return stats_->correction_fallbacks; }

std::vector<std::string> World::stage_names() const {
  std::vector<std::string> out;
  for (const auto& s : pipeline_->stages()) out.emplace_back(s->name());
  return out;
}

std::size_t World::neighbour_pairs() const { return nl_.pairs(); }

void World::adopt(Particles&& fresh) {
  p_ = std::move(fresh);
  p_.add_fields(pipeline_->fields());
  apply_boundaries(domain_, p_);
  integrator_->reset();  // its history was per particle
  nl_ = NeighbourList{};
  exact_ = NeighbourList{};
  for (auto& xb : x_built_) xb.clear();
  h_limit_.clear();
  lists_valid_ = false;
  rates_known_ = false;
  t_last_eval_ = -1.0;
  by_id_.clear();
  reorder();
}

void World::reorder() {
  // Morton order over cells of the kernel's support at the largest h: a cell's neighbours are mostly
  // in the cells next to it on the curve. Walls never move: sorted once, then the order is kept.
  const std::size_t nf = p_.fluid(), n = p_.size();
  const auto& h = p_[Field::H];
  double hmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, h[i]);
  double cell = kernel_.support() * hmax;
  if (cell <= 0.0) {  // point masses (h = 0): cells of 1/1024 of the extent
    double extent = 0.0;
    for (int k = 0; k < p_.dim(); ++k) {
      const auto [lo, hi] = std::minmax_element(p_.x[k].begin(), p_.x[k].begin() + static_cast<std::ptrdiff_t>(nf));
      if (nf > 0) extent = std::max(extent, *hi - *lo);
    }
    cell = extent / 1024.0;
  }
  std::vector<std::uint32_t> order = morton_order(p_, 0, nf, cell);
  if (by_id_.empty()) {
    const std::vector<std::uint32_t> walls = morton_order(p_, nf, n, cell);
    order.insert(order.end(), walls.begin(), walls.end());
  } else {
    for (std::size_t i = nf; i < n; ++i) order.push_back(static_cast<std::uint32_t>(i));
  }
  p_.permute(order);
  integrator_->permute(order);
  permute_neighbours(nl_, order);  // the lists stay valid for the current state
  permute_neighbours(exact_, order);
  for (auto& xb : x_built_)
    if (xb.size() == n) {
      const std::vector<double> old = xb;
      for (std::size_t k = 0; k < n; ++k) xb[k] = old[order[k]];
    }
  if (h_limit_.size() == n) {
    const std::vector<double> old = h_limit_;
    for (std::size_t k = 0; k < n; ++k) h_limit_[k] = old[order[k]];
  }
  by_id_.resize(n);
  for (std::size_t i = 0; i < n; ++i) by_id_[i] = static_cast<std::uint32_t>(i);
  std::sort(by_id_.begin(), by_id_.end(), [&](std::uint32_t a, std::uint32_t b) { return p_.id[a] < p_.id[b]; });
}

void World::reset_timings() {
  timings_.assign(1, StageTiming{"neighbours", 0.0, 0});
  for (const auto& s : pipeline_->stages()) timings_.push_back(StageTiming{std::string(s->name()), 0.0, 0});
}

StageContext World::context() const {
  // Stages get the particles mutable; const callers (potentials, limits) only read them.
  const NeighbourList& lists = pipeline_->exact_lists() ? exact_ : nl_;
  return StageContext{cfg_.params, kernel_, domain_, const_cast<Particles&>(p_), lists, h_limit_,
                      eta(), spacing_, wall_strength_, *stats_, since_};
}

void World::set_params(const Params& p) {
  const Params old = cfg_.params;
  if (p.physics != old.physics) {
    check_physics(*cfg_.scene, p.physics);  // throws before anything changes
    pipeline_ = std::make_unique<Pipeline>(p.physics, p_.dim());
    p_.add_fields(pipeline_->fields());
    start_shared_ = FieldSet{}.add(Field::Mass).add(Field::H);
    for (const EvolvedPair& e : pipeline_->evolved()) start_shared_.add(e.first);
    integrator_->reset();
    reset_timings();
  }
  cfg_.params = p;
  if (p.kernel.type != old.kernel.type) kernel_ = Kernel(p.kernel.type, p_.dim());
  if (p.time.integrator != old.time.integrator) integrator_ = make_integrator(p.time.integrator);
  current_ = false;  // rates depend on the parameters: re-evaluate before the next step
  rates_known_ = false;
  lists_valid_ = false;  // the kernel, h or the boundaries may have changed
  t_last_eval_ = -1.0;   // rates of other parameters make no first guess
  // new parameters may change dt and the energies legitimately (e.g. gravity switched on): the blow-up
  // guards measure from the next step on
  dt_first_ = 0.0;
  energy_scale_ = -1.0;
}

void World::evaluate(double t_eval) {
  since_ = t_last_eval_ >= 0.0 && t_eval >= t_last_eval_ ? t_eval - t_last_eval_ : 0.0;
  bound();
  const std::size_t n = p_.size();
  StageContext ctx = context();
  if (timings_.size() != pipeline_->stages().size() + 1) reset_timings();
  struct Rewrap {  // the wrapped coordinates come back however the stages end
    World& w;
    ~Rewrap() { w.rewrap(); }
  } rewrap_after{*this};
  for (int attempt = 0;; ++attempt) {
    auto t0 = std::chrono::steady_clock::now();
    if (pipeline_->uses_neighbours()) prepare_neighbours();  // pure N-body: no lists at all
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
    rewrap();
    if (complete) {
      add_push_acceleration(push_, domain_, p_);  // a body force of its own, after the stages' accelerations
      break;
    }
    lists_valid_ = false;  // an h outgrew its list: new lists from the new h
    ++h_overflows_;
    if (attempt > 20)
      throw DivergedError(-1, step_, t_, "h", "the smoothing length outgrows its neighbour lists on every rebuild");
  }
  ++evaluations_;
  t_last_eval_ = t_eval;
  rates_known_ = true;
}

void World::set_push(const Push& push) {
  const Push next = push.active() ? push : Push{};
  if (next == push_) return;
  push_ = next;
  pushes_.push_back(PushEvent{step_, push_});
  current_ = false;  // the rates of the current state change with the push
  dt_first_ = 0.0;
  energy_scale_ = -1.0;
}

double World::next_dt() {
  if (cfg_.params.time.dt > 0.0) return cfg_.params.time.dt;
  // The last evaluation's rates set dt (for RK4 and the predictor-corrector that is a stage within the
  // last step): evaluating again just for dt would double their cost.
  if (!rates_known_) { evaluate(); current_ = true; }
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
  const double dt_free = next_dt();
  double dt = std::min(dt_free, dt_max);
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    const std::int64_t id = fastest_particle();
    throw DivergedError(id, step_, t_, "dt", "no finite timestep (particle " + std::to_string(id) + " has the largest acceleration)");
  }
  // A blow-up that stays finite (velocities of 1e10, E_kin of 1e21) shows as a collapsing adaptive dt:
  // the run would crawl forever. A millionth of the first step's dt is far below any physical change.
  if (cfg_.params.time.dt <= 0.0) {
    if (dt_first_ <= 0.0) dt_first_ = dt_free;
    if (dt_free < 1e-6 * dt_first_) {
      const std::int64_t id = fastest_particle();
      char what[220];
      std::snprintf(what, sizeof what,
                    "the timestep collapsed to %.3g (the first step took %.3g; particle %lld has the largest "
                    "acceleration): the run is unstable",
                    dt_free, dt_first_, static_cast<long long>(id));
      throw DivergedError(id, step_, t_, "dt", what);
    }
  }
  PhaseSpace s = phase_space();
  const double t0 = t_;
  current_ = integrator_->step(s, [this, t0](double offset) { evaluate(t0 + offset); }, dt, current_);
  bound();
  t_ += dt;
  dt_last_ = dt;
  ++step_;
  after_step();
  check_finite();
  check_walls();
  check_h_solve();
  check_energy();
  check_reference();
}

void World::after_step() {
  bool due = false;
  for (const auto& s : pipeline_->stages()) due = due || s->acts_after(cfg_.params, step_);
  if (!due) return;
  prepare_neighbours();  // for the state the step ended in
  StageContext ctx = context();
  for (const auto& s : pipeline_->stages())
    if (s->acts_after(cfg_.params, step_)) {
      s->after_step(ctx);
      copy_ghost_fields(p_, s->shares());
    }
  rewrap();
  for (const auto& s : pipeline_->stages()) {
    Particles fresh;
    if (s->acts_after(cfg_.params, step_) && s->take_resampled(fresh)) adopt(std::move(fresh));
  }
  current_ = false;  // the state changed: the next step evaluates first
}

void World::advance_to(double t_target) {
  while (t_ < t_target * (1.0 - 1e-14) - 1e-300) {
    const double remaining = t_target - t_;
    double dt = next_dt();
    // land exactly on the target; avoid a sliver of a step at the end
    if (dt >= remaining) dt = remaining;
    else if (dt > 0.5 * remaining) dt = 0.5 * remaining;
    step(dt);
    if (t_ > t_target) t_ = t_target;
  }
}

}  // namespace sph
