// NeighbourCache: neighbour lists kept between evaluations (step_cost_bench, tests/bench/README.md): Verlet lists with
// a skin, for every scene with neighbours, periodic and mirror ghosts included.
//
// When lists are built, each particle gets h_limit, the largest h its list covers: reach times its h
// (reach = 1.1 for the Newton-Raphson h, 1.05 for an evolved h, 1 for a fixed h), more where dh/dt says
// h is growing fast. The lists hold every pair within (1 + skin) support max(h_limit_i, h_limit_j) of
// each other. While no particle has moved more than skin/2 support h_limit_i and no h passed its
// h_limit, every pair within support max(h_i, h_j) is in them, so the stages (which test each pair's
// distance) see exactly the pairs a fresh search would give, in the order of the build. Ghosts keep
// their sources and transforms and move with them. A particle that wraps through a periodic boundary
// keeps its stored coordinate wrapped; for the stages it is moved back to the image it had when the
// lists were built (unwrap, rewrap), so the lists and ghosts stay consistent. The lists are rebuilt
// when a particle moved too far, an h outgrew its list (the density solve reports it; the first guess
// of the solve, h + dh/dt dt, is checked before), or the parameters changed. Results depend on when
// lists were built (their order), never on threads.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "io/byte_stream.h"
#include "sph/neighbour_cache.h"

namespace sph {
namespace {

/// The lists reach this fraction of the support beyond h_limit; a particle may move half of it.
constexpr double kSkin = 0.15;

/// How far beyond the current h the lists reach at least: the Newton-Raphson solve may grow h by 10%
/// (more where dh/dt predicts it, see h_limit) before the lists are rebuilt; an evolved h changes by far
/// less than 5% in a step; a fixed h needs no margin. 1.1 instead of 1.2: lists of 44 instead of 53
/// entries per particle (box_random, 2D), 17% fewer candidates for every pair loop to test; builds rose
/// from 0.45 to 0.50 of the evaluations on Sedov, and no solve had to be redone (step_cost_bench).
double reach_of(HMode mode) {
  switch (mode) {
    case HMode::Variable: return 1.1;
    case HMode::Evolved: return 1.05;
    case HMode::Fixed: return 1.0;
  }
  return 1.2;
}

}  // namespace

bool NeighbourCache::fits(const Particles& p, const Domain& domain, double support, double since) const {
  const std::size_t n = p.size(), nf = p.fluid();
  if (!reuse_ || !valid_ || nl_.offset.size() != n + 1 || h_limit_.size() != n || x_built_[0].size() != n) return false;
  const double allowed = 0.5 * kSkin * support;  // times h_limit: half the skin
  const auto& h = p[Field::H];
  const double* hdot = p.has(Field::HRate) ? p[Field::HRate].data() : nullptr;
  std::array<double, 3> period{0.0, 0.0, 0.0};
  for (int k = 0; k < p.dim(); ++k)
    if (domain.bc[k] == Boundary::Periodic) period[k] = domain.length(k);
  int misfits = 0;  // a count: the same for any thread count
#pragma omp parallel for reduction(+ : misfits) if (nf >= kParallelMin)
  for (std::size_t i = 0; i < nf; ++i) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      double d = p.x[k][i] - x_built_[k][i];
      if (period[k] > 0.0) d -= period[k] * std::nearbyint(d / period[k]);  // the image of the build
      d2 += d * d;
    }
    const double lim = allowed * h_limit_[i];
    const double h_next = hdot ? h[i] + std::max(0.0, hdot[i]) * since : h[i];  // the solve's first guess
    misfits += (d2 < lim * lim) & (h_next <= h_limit_[i]) ? 0 : 1;
  }
  return misfits == 0;
}

void NeighbourCache::unwrap(Particles& p, const Domain& domain) {
  unwrapped_.clear();
  const std::size_t nf = p.fluid();
  for (int k = 0; k < p.dim(); ++k) {
    if (domain.bc[k] != Boundary::Periodic) continue;
    const double L = domain.length(k);
    auto& x = p.x[k];
    const auto& xb = x_built_[k];
    for (std::size_t i = 0; i < nf; ++i) {
      const double m = std::nearbyint((xb[i] - x[i]) / L);
      if (m == 0.0) continue;
      unwrapped_.push_back(Unwrapped{static_cast<std::uint32_t>(i), k, x[i]});
      x[i] += m * L;
    }
  }
}

void NeighbourCache::rewrap(Particles& p) {
  for (const Unwrapped& u : unwrapped_) p.x[u.axis][u.i] = u.x;
  unwrapped_.clear();
}

void NeighbourCache::prepare(Particles& p, const ListRequest& rq) {
  const double support = rq.kernel.support();
  if (fits(p, rq.domain, support, rq.since)) {
    unwrap(p, rq.domain);
    update_ghost_positions(p);
    copy_ghost_velocity(p);
    copy_ghost_fields(p, rq.shared);
  } else {
    build(p, rq);
  }
  if (rq.exact) filter_neighbours(p, p[Field::H], support, nl_, exact_);
}

void NeighbourCache::build(Particles& p, const ListRequest& rq) {
  const std::size_t n = p.size(), nf = p.fluid();
  const auto& h = p[Field::H];
  const double support = rq.kernel.support();
  // h_limit: reach h, and more where h grows: by twice its growth over the time the lists are
  // expected to last (until the fastest particle has used its skin), at most twice reach h
  const double reach = reach_of(rq.smoothing);
  const double* hdot = p.has(Field::HRate) && rq.have_rates ? p[Field::HRate].data() : nullptr;
  double life = 0.0;
  if (hdot) {
    double vmax_over_h = 0.0;
#pragma omp parallel for reduction(max : vmax_over_h) if (nf >= kParallelMin)
    for (std::size_t i = 0; i < nf; ++i) vmax_over_h = std::max(vmax_over_h, p.vel(i).norm() / h[i]);
    life = vmax_over_h > 0.0 ? 0.5 * kSkin * support * reach / vmax_over_h : 0.0;
    if (rq.dt_last > 0.0) life = std::min(life > 0.0 ? life : 16.0 * rq.dt_last, 16.0 * rq.dt_last);
  }
  h_limit_.resize(n);
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double growth = hdot && i < nf ? std::max(0.0, hdot[i]) * life / h[i] : 0.0;
    h_limit_[i] = reach * std::min(1.0 + 2.0 * growth, 2.0) * h[i];
  }
  double hl_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) hl_max = std::max(hl_max, h_limit_[i]);
  const double radius = support * (1.0 + kSkin);
  make_ghosts(rq.domain, radius * hl_max, p);  // throws GhostOverflow
  copy_ghost_velocity(p);
  copy_ghost_fields(p, rq.shared);
  // the lists' h: h_limit for every particle, ghosts from their sources
  reach_h_.resize(p.total());
  std::copy(h_limit_.begin(), h_limit_.end(), reach_h_.begin());
  for (std::size_t g = 0; g < p.ghost_src.size(); ++g) reach_h_[n + g] = h_limit_[p.ghost_src[g]];
  radius_ = radius;
  if (rq.by_rows) {  // the grid now, each list when an evaluation first visits its particle
    build_neighbour_grid(p, reach_h_, radius, nl_);
    gathered_.assign(n, 0);
    missing_ = n;
  } else {
    build_neighbours(p, reach_h_, radius, nl_);
    gathered_.clear();
    missing_ = 0;
  }
  for (int k = 0; k < 3; ++k) x_built_[k].assign(p.x[k].begin(), p.x[k].begin() + static_cast<std::ptrdiff_t>(n));
  valid_ = true;
  ++builds_;
}

void NeighbourCache::gather(std::span<const std::uint32_t> rows) const {
  std::vector<std::uint32_t> todo;
  for (std::uint32_t i : rows)
    if (!gathered_[i]) { todo.push_back(i); gathered_[i] = 1; }
  gather_neighbour_rows(x_built_, reach_h_, radius_, todo, nl_);
  missing_ -= todo.size();
}

void NeighbourCache::need(std::span<const std::uint32_t> rows) {
  if (missing_ > 0) gather(rows);
}

const NeighbourList& NeighbourCache::every_list() const {
  if (missing_ > 0) {
    std::vector<std::uint32_t> all(gathered_.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
    gather(all);
  }
  return nl_;
}

void NeighbourCache::clear() {
  gathered_.clear();
  missing_ = 0;
  nl_ = NeighbourList{};
  exact_ = NeighbourList{};
  for (auto& xb : x_built_) xb.clear();
  h_limit_.clear();
  valid_ = false;
}

void NeighbourCache::permute(const std::vector<std::uint32_t>& order) {
  const std::size_t n = order.size();
  // the lists stay valid for the current state; the kept grid is renumbered too, for the lists not yet gathered
  permute_neighbours(nl_, order);
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
  if (gathered_.size() == n) {
    const std::vector<std::uint8_t> old = gathered_;
    for (std::size_t k = 0; k < n; ++k) gathered_[k] = old[order[k]];
  }
  if (reach_h_.size() >= n) {  // real particles first, then the ghosts (which keep their slots)
    const std::vector<double> old(reach_h_.begin(), reach_h_.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t k = 0; k < n; ++k) reach_h_[k] = old[order[k]];
  }
}

}  // namespace sph
