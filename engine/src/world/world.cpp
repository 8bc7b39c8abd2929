// The step loop: boundaries -> ghosts -> neighbours -> density/h -> EOS -> forces, driven by the
// chosen integrator (seed 000 §3.5, steps 1–9).
#include "sph/world.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "sph/hydro.h"

namespace sph {
namespace {

constexpr double kSkin = 1.2;  ///< neighbour lists reach 1.2 x the current h, so h may grow 20% in a solve

}  // namespace

DivergedError::DivergedError(std::int64_t particle_, std::int64_t step_, double t_, const std::string& field_)
    : std::runtime_error("simulation diverged: particle " + std::to_string(particle_) + " has a non-finite " +
                         field_ + " at step " + std::to_string(step_) + " (t = " + std::to_string(t_) + ")"),
      particle(particle_), step(step_), t(t_), field(field_) {}

World::World(const RunConfig& cfg) : cfg_(cfg), kernel_(cfg.params.kernel, cfg.scene->dim) {
  SceneSetup setup = cfg_.scene->build(cfg_.params, cfg_.values);
  p_ = std::move(setup.particles);
  domain_ = setup.domain;
  integrator_ = make_integrator(cfg_.params.integrator);
  if (cfg_.scene->reference) reference_ = cfg_.scene->reference(cfg_.params, cfg_.values);
  apply_boundaries(domain_, p_);
  evaluate();
  if (cfg_.scene->density_anchor) {
    const auto [k, rho_target] = cfg_.scene->density_anchor(cfg_.values);
    const double scale = rho_target / p_[Field::Density][k];
    for (std::size_t i = 0; i < p_.size(); ++i) p_[Field::Mass][i] *= scale;
    evaluate();
  }
  if (cfg_.scene->initial_pressure && p_.has(Field::Energy)) {
    auto& u = p_[Field::Energy];
    const auto& rho = p_[Field::Density];
    for (std::size_t i = 0; i < p_.size(); ++i)
      u[i] = cfg_.scene->initial_pressure(p_.pos(i), cfg_.values) / ((cfg_.params.gamma - 1.0) * rho[i]);
    evaluate();
  }
  current_ = true;
  check_finite();
}

World::~World() = default;

double World::eta() const { return cfg_.params.eta > 0.0 ? cfg_.params.eta : kernel_.default_eta(); }

void World::set_params(const Params& p) {
  const Params old = cfg_.params;
  cfg_.params = p;
  if (p.kernel != old.kernel) kernel_ = Kernel(p.kernel, p_.dim());
  if (p.integrator != old.integrator) integrator_ = make_integrator(p.integrator);
  current_ = false;  // forces depend on the parameters: re-evaluate before the next step
  rates_known_ = false;
}

void World::evaluate() {
  const Modules& mod = cfg_.scene->modules;
  apply_boundaries(domain_, p_);
  const std::size_t n = p_.size();
  auto& h = p_[Field::H];
  for (int attempt = 0;; ++attempt) {
    double hmax = 0.0;
#pragma omp parallel for reduction(max : hmax) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, h[i]);
    make_ghosts(domain_, kernel_.support() * kSkin * hmax, p_);
    copy_ghost_field(p_, Field::Mass);
    copy_ghost_field(p_, Field::H);
    build_neighbours(p_, h, kernel_.support() * kSkin, nl_);
    h_limit_.resize(n);
#pragma omp parallel for if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) h_limit_[i] = kSkin * h[i];
    if (solve_density(kernel_, cfg_.params, eta(), p_, nl_, h_limit_, dstats_)) break;
    if (attempt > 20) throw DivergedError(-1, step_, t_, "smoothing length (h does not converge)");
  }
  if (mod.hydro) {
    ideal_gas_eos(cfg_.params, p_);
    for (Field f : {Field::Density, Field::H, Field::Omega, Field::Pressure, Field::SoundSpeed})
      copy_ghost_field(p_, f);
    if (p_.has(Field::Energy)) copy_ghost_field(p_, Field::Energy);
    copy_ghost_velocity(p_);
    Params prm = cfg_.params;
    if (!mod.viscosity) prm.alpha = prm.beta = 0.0;
    if (!mod.conductivity) prm.alpha_u = 0.0;
    hydro_forces(kernel_, prm, p_, nl_, mod.energy);
  }
  ++evaluations_;
  rates_known_ = true;
}

double World::next_dt() {
  if (cfg_.params.dt > 0.0) return cfg_.params.dt;
  // The last evaluation's signal speeds set dt (for RK4 and the predictor-corrector that is a stage
  // within the last step): evaluating again just for dt would double their cost.
  if (!rates_known_) { evaluate(); current_ = true; }
  const std::size_t n = p_.size();
  const auto& h = p_[Field::H];
  const auto& vs = p_[Field::SignalSpeed];
  double dt = 1e300;  // a minimum: the same for any thread count
#pragma omp parallel for reduction(min : dt) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (vs[i] > 0.0) dt = std::min(dt, h[i] / vs[i]);  // Courant condition
    const double a = std::sqrt(p_.a[0][i] * p_.a[0][i] + p_.a[1][i] * p_.a[1][i] + p_.a[2][i] * p_.a[2][i]);
    if (a > 0.0) dt = std::min(dt, std::sqrt(h[i] / a));  // force condition
  }
  return cfg_.params.cfl * dt;
}

void World::step(double dt_max) {
  double dt = std::min(next_dt(), dt_max);
  if (!(dt > 0.0)) throw DivergedError(-1, step_, t_, "timestep");
  PhaseSpace s;
  s.dim = p_.dim();
  s.n = p_.size();
  for (int k = 0; k < 3; ++k) { s.x[k] = &p_.x[k]; s.v[k] = &p_.v[k]; s.a[k] = &p_.a[k]; }
  if (cfg_.scene->modules.energy) { s.u = &p_[Field::Energy]; s.dudt = &p_[Field::EnergyRate]; }
  current_ = integrator_->step(s, [this] { evaluate(); }, dt, current_);
  apply_boundaries(domain_, p_);
  t_ += dt;
  dt_last_ = dt;
  ++step_;
  check_finite();
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

void World::check_finite() const {
  const std::size_t n = p_.size();
  auto bad = [&](const std::vector<double>& a, const char* name) {
    std::size_t first = n;  // lowest index of a non-finite value: the same for any thread count
#pragma omp parallel for reduction(min : first) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(a[i])) first = std::min(first, i);
    if (first < n) throw DivergedError(p_.id[first], step_, t_, name);
  };
  const char* xn[3] = {"x", "y", "z"};
  const char* vn[3] = {"vx", "vy", "vz"};
  for (int k = 0; k < p_.dim(); ++k) { bad(p_.x[k], xn[k]); bad(p_.v[k], vn[k]); }
  for (Field f : {Field::Density, Field::H, Field::Energy, Field::Pressure})
    if (p_.has(f)) bad(p_[f], std::string(info(f).key).c_str());
}

}  // namespace sph
