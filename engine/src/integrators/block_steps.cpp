// Individual time steps on a power-of-two hierarchy (see block_steps.h). Every loop is per particle or
// an integer reduction, so the steps are the same for any thread count.
#include "block_steps.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/parallel.h"
#include "integrators/landing_step.h"

namespace sph {
namespace {

constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();

constexpr std::size_t kNoParticle = std::numeric_limits<std::size_t>::max();

/// The fluid particle behind list entry j (a ghost stands for its source), or kNoParticle (walls).
std::size_t fluid_of(const Particles& p, std::uint32_t j) {
  std::size_t r = j;
  if (r >= p.size()) {
    if (r - p.size() >= p.ghost_src.size()) return kNoParticle;
    r = p.ghost_src[r - p.size()];
  }
  return r < p.fluid() ? r : kNoParticle;
}

/// The neighbours of fluid particle i in the lists (none in a pipeline without lists: point masses).
std::span<const std::uint32_t> list_of(const NeighbourList& nl, std::size_t i) {
  if (nl.offset.size() <= i + 1) return {};
  return nl.of(i);
}

/// The shortest step among the fluid neighbours of fluid particle i (walls do not step) [ticks];
/// kNone without any.
std::int64_t shortest_near(const Particles& p, const NeighbourList& nl, std::size_t i,
                           const std::vector<std::int64_t>& len) {
  std::int64_t m = kNone;
  for (std::uint32_t j : list_of(nl, i)) {
    const std::size_t r = fluid_of(p, j);
    if (r != kNoParticle && r != i) m = std::min(m, len[r]);
  }
  return m;
}

/// A step more than this many times the wanted dt is reported (a factor the Courant factor's margin takes).
constexpr double kTooLong = 2.0;

/// Neighbours differ by at most two levels: a step at most four times the shortest near it.
constexpr std::int64_t kLimiter = 4;

}  // namespace

BlockSteps::BlockSteps(int levels) : levels_(levels), ticks_(std::int64_t{1} << (levels - 1)) {
  if (levels < 1 || levels > 40) throw std::invalid_argument("BlockSteps: levels out of range");
}

double BlockSteps::block_length(const std::vector<double>& want) const {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (double w : want) { lo = std::min(lo, w); hi = std::max(hi, w); }
  // the shortest wanted step times a power of two, at most the longest: the particle that wants the
  // shortest step takes exactly it, as with one global step
  double block = lo;
  for (std::int64_t k = 1; k < ticks_ && 2.0 * block <= hi; k *= 2) block *= 2.0;
  return block;
}

void BlockSteps::begin_block(PhaseSpace& s, const Particles& p, const Hooks& hooks, double dt_max) {
  const std::size_t n = s.n;
  std::vector<double> want;
  hooks.want(want);
  tau_ = landing_step(block_length(want), dt_max) / static_cast<double>(ticks_);
  tick_ = 0;
  len_.assign(n, ticks_);
  begin_.assign(n, 0);
  on_.assign(n, 1);
  wake_.assign(n, 0);
  level_.assign(n, ticks_);
  active_.resize(n);
  for (std::size_t i = 0; i < n; ++i) active_[i] = static_cast<std::uint32_t>(i);
  summed_ = active_;
  for (int k = 0; k < s.dim; ++k) { vhalf_[k].resize(n); a0_[k].resize(n); }
  yhalf_.assign(s.evolved.size(), std::vector<double>(n));
  r0_.assign(s.evolved.size(), std::vector<double>(n));
  choose_levels(p, hooks.lists(), want);
  open(s);
  in_block_ = true;
  find_next_tick();
}

void BlockSteps::choose_levels(const Particles& p, const NeighbourList& nl, const std::vector<double>& want) {
  const std::size_t n = len_.size(), na = active_.size();
  level_.resize(n, ticks_);
  std::vector<std::int64_t> limited(na);
  std::int64_t too_long = 0;
  // the longest power-of-two step within the wanted dt
#pragma omp parallel for reduction(+ : too_long) if (na >= kParallelMin)
  for (std::size_t k = 0; k < na; ++k) {
    const std::size_t i = active_[k];
    std::int64_t len = ticks_;
    while (len > 1 && static_cast<double>(len) * tau_ > want[i]) len >>= 1;
    if (tau_ > kTooLong * want[i]) ++too_long;
    level_[i] = len;
  }
  too_long_ += too_long;
  // the limiter on the wanted levels, until none exceeds four times its neighbours' shortest (Jacobi passes)
  for (bool changed = true; changed;) {
    int any = 0;
#pragma omp parallel for reduction(| : any) if (na >= kParallelMin)
    for (std::size_t k = 0; k < na; ++k) {
      const std::size_t i = active_[k];
      const std::int64_t m = shortest_near(p, nl, i, level_);
      limited[k] = m != kNone && level_[i] > kLimiter * m ? kLimiter * m : level_[i];
      any |= limited[k] != level_[i] ? 1 : 0;
    }
    changed = any != 0;
    for (std::size_t k = 0; k < na; ++k) level_[active_[k]] = limited[k];
  }
  // the step: the level, or shorter until it starts on a multiple of itself (it grows back later)
  for (std::uint32_t i : active_) {
    std::int64_t len = level_[i];
    while (tick_ % len != 0) len >>= 1;
    len_[i] = len;
    begin_[i] = tick_;
  }
  // an inactive neighbour stepping more than four times the level is woken at the next sub-step (a
  // scatter over the active particles' lists that only sets flags)
  wake_.resize(n, 0);
  if (na == n) return;  // every particle active: none to wake
  for (std::uint32_t i : active_)
    for (std::uint32_t j : list_of(nl, i))
      if (const std::size_t r = fluid_of(p, j); r != kNoParticle && !on_[r] && len_[r] > kLimiter * level_[i]) wake_[r] = 1;
}

void BlockSteps::open(const PhaseSpace& s) {
  const std::size_t n = s.n;
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_[i]) continue;
    const double half = 0.5 * static_cast<double>(len_[i]) * tau_;
    for (int k = 0; k < s.dim; ++k) {
      a0_[k][i] = (*s.a[k])[i];
      vhalf_[k][i] = (*s.v[k])[i] + half * a0_[k][i];
    }
    for (std::size_t e = 0; e < s.evolved.size(); ++e) {
      r0_[e][i] = (*s.evolved[e].rate)[i];
      yhalf_[e][i] = (*s.evolved[e].y)[i] + half * r0_[e][i];
    }
  }
}

void BlockSteps::find_next_tick() {
  std::int64_t next = ticks_;
  const std::size_t n = len_.size();
#pragma omp parallel for reduction(min : next) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) next = std::min(next, begin_[i] + len_[i]);
  next_tick_ = next;
}

void BlockSteps::mark_summed(const Particles& p, const NeighbourList& nl) {
  const std::size_t n = on_.size();
  if (active_.size() == n) {  // every particle: no scatter
    summed_ = active_;
    return;
  }
  near_.assign(n, 0);
  for (std::uint32_t i : active_) {
    near_[i] = 1;
    for (std::uint32_t j : list_of(nl, i))
      if (const std::size_t r = fluid_of(p, j); r != kNoParticle) near_[r] = 1;
  }
  summed_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (near_[i]) summed_.push_back(static_cast<std::uint32_t>(i));
}

void BlockSteps::mark_active(PhaseSpace& s) {
  const std::size_t n = s.n;
  wake_.resize(n, 0);
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) on_[i] = begin_[i] + len_[i] == tick_ || wake_[i] ? 1 : 0;
  std::fill(wake_.begin(), wake_.end(), 0);
  active_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (on_[i]) active_.push_back(static_cast<std::uint32_t>(i));
  // a woken particle's step ends now: its opening kick was for the whole step, keep the part it ran
  // (kick and drift then are those of a step of the length it ran)
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_[i] || begin_[i] + len_[i] == tick_) continue;
    const double cut = 0.5 * static_cast<double>(begin_[i] + len_[i] - tick_) * tau_;
    const double ran = static_cast<double>(tick_ - begin_[i]) * tau_;  // it drifted that long with v_1/2
    for (int k = 0; k < s.dim; ++k) {
      vhalf_[k][i] -= cut * a0_[k][i];
      (*s.x[k])[i] -= ran * cut * a0_[k][i];  // and so the drift of its shorter step
    }
    for (std::size_t e = 0; e < s.evolved.size(); ++e) yhalf_[e][i] -= cut * r0_[e][i];
    len_[i] = tick_ - begin_[i];
  }
}

double BlockSteps::step(PhaseSpace& s, const Particles& p, const Hooks& hooks, double dt_max) {
  if (!in_block_) begin_block(s, p, hooks, dt_max);
  const std::size_t n = s.n;
  const double dt = static_cast<double>(next_tick_ - tick_) * tau_;
  for (int k = 0; k < s.dim; ++k) {  // drift: x += v_1/2 dt, every particle
    std::vector<double>& x = *s.x[k];
#pragma omp parallel for if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) x[i] += dt * vhalf_[k][i];
  }
  tick_ = next_tick_;
  mark_active(s);
  // every particle's state now: the active ones' end of step (as the global leapfrog predicts it), the
  // others' prediction from their opening kick
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const double off = (static_cast<double>(tick_ - begin_[i]) - 0.5 * static_cast<double>(len_[i])) * tau_;
    for (int k = 0; k < s.dim; ++k) (*s.v[k])[i] = vhalf_[k][i] + off * a0_[k][i];
    for (std::size_t e = 0; e < s.evolved.size(); ++e) (*s.evolved[e].y)[i] = yhalf_[e][i] + off * r0_[e][i];
  }
  hooks.eval(dt);
  // closing kick of the active particles; the others keep the rates of their opening kick
#pragma omp parallel for if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const bool on = on_[i] != 0;
    const double half = 0.5 * static_cast<double>(len_[i]) * tau_;
    for (int k = 0; k < s.dim; ++k) {
      if (on) (*s.v[k])[i] = vhalf_[k][i] + half * (*s.a[k])[i];
      else (*s.a[k])[i] = a0_[k][i];
    }
    for (std::size_t e = 0; e < s.evolved.size(); ++e) {
      if (on) (*s.evolved[e].y)[i] = yhalf_[e][i] + half * (*s.evolved[e].rate)[i];
      else (*s.evolved[e].rate)[i] = r0_[e][i];
    }
  }
  if (tick_ == ticks_) {  // every step ended: the block is over and the rates are current
    in_block_ = false;
    return dt;
  }
  std::vector<double> want;
  hooks.want(want);
  choose_levels(p, hooks.lists(), want);
  open(s);
  find_next_tick();
  return dt;
}

void BlockSteps::write_levels(std::vector<double>& level) const {
  const std::size_t n = std::min(level.size(), len_.size());
  for (std::size_t i = 0; i < n; ++i) {
    int k = 0;
    for (std::int64_t l = len_[i]; l < ticks_; l *= 2) ++k;
    level[i] = k;
  }
}

void BlockSteps::permute(std::span<const std::uint32_t> order) {
  const std::size_t n = len_.size();
  if (n == 0) return;
  auto reorder = [&](auto& a) {
    if (a.size() != n) return;
    auto old = a;
    for (std::size_t k = 0; k < n; ++k) a[k] = old[order[k]];
  };
  reorder(len_);
  reorder(begin_);
  reorder(on_);
  reorder(wake_);
  reorder(level_);
  for (int k = 0; k < 3; ++k) { reorder(vhalf_[k]); reorder(a0_[k]); }
  for (auto& y : yhalf_) reorder(y);
  for (auto& r : r0_) reorder(r);
}

}  // namespace sph
