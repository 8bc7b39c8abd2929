#include "inspect/fresh_evaluation.h"

#include <algorithm>
#include <stdexcept>

namespace sph {
namespace {

/// Lists reach this factor beyond the current h: the Newton-Raphson h solve may grow h by 20% before
/// its particle's list must be rebuilt (the longest skin of the World's; pair loops filter the rest).
constexpr double kReach = 1.2;

Vec3 acceleration(const Particles& p, std::size_t i) { return {p.a[0][i], p.a[1][i], p.a[2][i]}; }
double energy_rate(const Particles& p, std::size_t i) { return p.has(Field::EnergyRate) ? p[Field::EnergyRate][i] : 0.0; }

/// Ghosts and lists for the copy's current h (what NeighbourCache::prepare does without Verlet lists).
void prepare(FreshEvaluation& e, const Kernel& K, const Domain& d, FieldSet start_shared) {
  Particles& p = e.p;
  const std::size_t n = p.size();
  const auto& h = p[Field::H];
  const double hmax = n ? *std::max_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(n)) : 0.0;
  make_ghosts(d, K.support() * kReach * hmax, p);
  copy_ghost_velocity(p);
  copy_ghost_fields(p, start_shared);
  e.h_limit.resize(n);
  for (std::size_t k = 0; k < n; ++k) e.h_limit[k] = kReach * h[k];
  build_neighbours(p, p[Field::H], K.support() * kReach, e.nl);
}

}  // namespace

StageContext fresh_context(const FreshInputs& in, FreshEvaluation& e) {
  return StageContext{in.prm, in.kernel, in.domain, e.p, e.nl, e.h_limit, in.eta, in.spacing, in.wall_strength, e.stats};
}

FreshEvaluation evaluate_fresh(const FreshInputs& in, const Particles& state, std::size_t i) {
  FreshEvaluation e;
  e.pipeline = std::make_unique<Pipeline>(in.prm, state.dim());
  e.p = state;
  e.p.resize_total(state.size());  // drop the old ghosts: prepare() makes the copy's own
  FieldSet start_shared = FieldSet{}.add(Field::Mass).add(Field::H);
  for (const EvolvedPair& ev : e.pipeline->evolved()) start_shared.add(ev.first);
  StageContext ctx = fresh_context(in, e);
  const std::size_t n = e.p.size();
  for (int attempt = 0;; ++attempt) {
    if (e.pipeline->uses_neighbours()) prepare(e, in.kernel, in.domain, start_shared);
    if (!e.pipeline->sets_acceleration())
      for (int k = 0; k < 3; ++k) std::fill(e.p.a[k].begin(), e.p.a[k].begin() + static_cast<std::ptrdiff_t>(n), 0.0);
    e.deltas.clear();
    bool complete = true;
    for (const auto& stage : e.pipeline->stages()) {
      const Vec3 a0 = acceleration(e.p, i);
      const double du0 = energy_rate(e.p, i);
      if (!stage->run(ctx)) { complete = false; break; }
      copy_ghost_fields(e.p, stage->shares());
      StageDelta d;
      d.stage = std::string(stage->name());
      d.sets = stage->sets_acceleration();
      d.a = d.sets ? acceleration(e.p, i) : acceleration(e.p, i) - a0;
      d.dudt = d.sets ? energy_rate(e.p, i) : energy_rate(e.p, i) - du0;
      e.deltas.push_back(std::move(d));
    }
    if (complete) return e;
    if (attempt > 20) throw std::runtime_error("inspect: the smoothing length outgrows its neighbour lists");
  }
}

}  // namespace sph
