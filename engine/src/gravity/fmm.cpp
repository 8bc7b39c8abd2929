// The fast multipole method (gravity/fmm.h): the multipoles bottom up, the relative guard's estimate
// walk, and the dual walk from the root, serial down to a few hundred subtrees and parallel below.
//
// Why order 5: at N = 1e5 on a Plummer sphere (eps = 0.01, theta = 0.8, tol = 1e-3, two threads;
// tests/bench/gravity_fmm_bench.cpp) orders 3, 4, 5, 6 took 0.52, 0.53, 0.44, 0.69 s with RMS force
// errors 1.0e-3, 2.6e-4, 1.1e-4, 6.6e-5 (99th percentile 3.8e-3, 8.3e-4, 3.6e-4, 2.4e-4): below 5 the
// guard needs more cell and leaf pairs and the error is still larger, above it each cell pair costs
// more than their smaller number saves.
#include "gravity/fmm.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "gravity/fmm_walk.h"

namespace sph::gravity {
namespace {

/// Depth below which subtrees are walked in parallel (at most 8^3 subtrees in 3D).
constexpr std::size_t kParallelDepth = 3;

}  // namespace

void FastMultipole::build(const Sources& s, std::uint32_t leaf_size) {
  tree_.build(s, leaf_size);  // it keeps positions, masses and h in tree order: tx(), tm(), th()
  const auto& nodes = tree_.nodes();
  const std::size_t size = ex_->size();
  M_.assign(nodes.size() * size, 0.0);
  for (std::size_t b = nodes.size(); b-- > 0;) {  // children come after their parent
    const TreeNode& nd = nodes[b];
    double* Mb = &M_[b * size];
    if (nd.n_child == 0) {
      for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q)
        ex_->p2m(tm()[q], tx()[0][q] - nd.com[0], tx()[1][q] - nd.com[1], tx()[2][q] - nd.com[2], Mb);
    } else {
      for (std::uint32_t ch = nd.child; ch < nd.child + nd.n_child; ++ch) {
        const TreeNode& c = nodes[ch];
        ex_->m2m(&M_[ch * size], c.com[0] - nd.com[0], c.com[1] - nd.com[1], c.com[2] - nd.com[2], Mb);
      }
    }
  }
}

bool FastMultipole::accepts(const Criterion& c, double mass, double rs, double R2, double hmax,
                            std::uint32_t node_b) const {
  const double open = rs * c.inv_theta;
  if (!(R2 > open * open)) return false;
  if (c.kernel) {
    const double reach = rs + c.support * hmax;
    if (!(R2 > reach * reach)) return false;
  }
  if (c.amin) {  // the expansion's error estimate M_A rho^P / (R^2 (1 - rho)^2), rho = rs / R, within
                 // tol min|a|_B
    const double rho = std::sqrt(rs * rs / R2);
    double rho_p = rho;  // rho^P by products: std::pow took 7% of an evaluation at N = 1e5
    for (int k = 1; k < c.order; ++k) rho_p *= rho;
    const double ratio = rho_p / ((1.0 - rho) * (1.0 - rho));
    if (mass * ratio > c.tol * (*c.amin)[node_b] * R2) return false;
  }
  return true;
}

bool FastMultipole::separated(const Criterion& c, const TreeNode& a, const TreeNode& b, std::uint32_t node_b) const {
  const double dx = b.com[0] - a.com[0], dy = b.com[1] - a.com[1], dz = b.com[2] - a.com[2];
  return accepts(c, a.mass, a.bmax + b.bmax, dx * dx + dy * dy + dz * dz, std::max(a.hmax, b.hmax), node_b);
}

bool FastMultipole::reaches_particles(const Criterion& c, const TreeNode& a, const TreeNode& b,
                                      std::uint32_t node_b) const {
  const double dx = b.com[0] - a.com[0], dy = b.com[1] - a.com[1], dz = b.com[2] - a.com[2];
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz) - b.bmax;  // to B's nearest possible particle
  return d > 0.0 && accepts(c, a.mass, a.bmax, d * d, std::max(a.hmax, b.hmax), node_b);
}

void FastMultipole::visit(std::uint32_t b, const std::vector<std::uint32_t>& near, Walk& w, std::size_t depth) const {
  const auto& nodes = tree_.nodes();
  const TreeNode& nb = nodes[b];
  std::vector<std::uint32_t>& todo = w.todo[depth];
  std::vector<std::uint32_t>& keep = w.keep[depth];
  todo.assign(near.begin(), near.end());
  keep.clear();
  w.far.clear();
  w.direct.clear();
  const bool b_leaf = nb.n_child == 0;
  for (std::size_t q = 0; q < todo.size(); ++q) {  // in list order: the sums' order is fixed
    const std::uint32_t a = todo[q];
    const TreeNode& na = nodes[a];
    if (na.mass == 0.0) continue;
    if (separated(*w.crit, na, nb, b)) {
      w.far.push_back(a);
    } else if (b_leaf && na.n_child > 0 && reaches_particles(*w.crit, na, nb, b)) {
      w.direct.push_back(a);  // a large leaf B: A's multipoles at each of its particles (M2P)
    } else if (na.n_child == 0 || (!b_leaf && na.bmax <= nb.bmax)) {
      keep.push_back(a);  // summed pair by pair (leaf b), or tested again against b's children
    } else {
      for (std::uint32_t ch = na.child; ch < na.child + na.n_child; ++ch) todo.push_back(ch);
    }
  }
  far_field(b, w);
  if (b_leaf) {
    leaf(b, keep, w);
    return;
  }
  for (std::uint32_t ch = nb.child; ch < nb.child + nb.n_child; ++ch) {
    if (w.live && live_[ch] == 0) continue;  // no sink below: nothing to compute there
    const TreeNode& nc = nodes[ch];
    ex_->l2l(L(b), nc.com[0] - nb.com[0], nc.com[1] - nb.com[1], nc.com[2] - nb.com[2], L(ch));
    // a subtree is left for the parallel pass below kParallelDepth or once it holds 1/64 of the particles
    if (w.deferred && (depth + 1 >= kParallelDepth || 64 * std::size_t{nc.count} <= nodes[0].count))
      w.deferred->emplace_back(ch, keep);
    else
      visit(ch, keep, w, depth + 1);
  }
}

void FastMultipole::far_field(std::uint32_t b, Walk& w) const {
  const auto& nodes = tree_.nodes();
  const TreeNode& nb = nodes[b];
  static const std::vector<double> zero(Expansion::kMaxSize, 0.0);
  for (std::size_t q = 0; q < w.far.size(); q += 4) {  // four cells at a time, the last group padded
    const double* Ms[4];
    double R[4][3];
    for (std::size_t v = 0; v < 4; ++v) {
      if (q + v < w.far.size()) {
        const TreeNode& na = nodes[w.far[q + v]];
        Ms[v] = M(w.far[q + v]);
        for (int k = 0; k < 3; ++k) R[v][k] = nb.com[k] - na.com[k];
      } else {
        Ms[v] = zero.data();
        R[v][0] = 1.0;
        R[v][1] = R[v][2] = 0.0;
      }
    }
    ex_->m2l4(Ms, R, w.e2, L(b));
  }
  w.counts.m2l += w.far.size();
}


void FastMultipole::mark_sinks(const std::uint8_t* active) const {
  const auto& nodes = tree_.nodes();
  const auto& order = tree_.order();
  sink_.resize(order.size());
  for (std::size_t t = 0; t < order.size(); ++t) sink_[t] = active[order[t]] ? 1 : 0;
  live_.assign(nodes.size(), 0);
  for (std::size_t b = nodes.size(); b-- > 0;) {  // children come after their parent
    const TreeNode& nd = nodes[b];
    if (nd.n_child == 0) {
      for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) live_[b] += sink_[q];
    } else {
      for (std::uint32_t ch = nd.child; ch < nd.child + nd.n_child; ++ch) live_[b] += live_[ch];
    }
  }
}

void FastMultipole::walk(const PairLaw& law, const Criterion& c, Result& out, bool sinks_only) const {
  const auto& nodes = tree_.nodes();
  L_.assign(nodes.size() * ex_->size(), 0.0);
  if (sinks_only && live_[0] == 0) return;
  const double e2 = c.kernel ? 0.0 : law.eps2;
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> deferred;
  Walk top;
  top.law = &law;
  top.crit = &c;
  top.e2 = e2;
  top.out = &out;
  top.deferred = &deferred;
  top.live = sinks_only;
  visit(0, {0}, top, 0);  // the top levels, serial; below kParallelDepth the subtrees are deferred
  std::size_t m2l = top.counts.m2l, pairs = top.counts.pairs;
  const auto jobs = static_cast<std::ptrdiff_t>(deferred.size());
#pragma omp parallel reduction(+ : m2l, pairs) if (jobs > 1)
  {
    Walk w;
    w.law = &law;
    w.crit = &c;
    w.e2 = e2;
    w.out = &out;
    w.live = sinks_only;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t k = 0; k < jobs; ++k) {
      const auto& job = deferred[static_cast<std::size_t>(k)];
      visit(job.first, job.second, w, nodes[job.first].depth);
    }
    m2l += w.counts.m2l;
    pairs += w.counts.pairs;
  }
  out.node_terms += m2l;
  out.pair_terms += pairs;
}

void FastMultipole::evaluate(const Sources& s, const PairLaw& law, double G, double theta, Result& out,
                             double tol) const {
  const std::size_t n = s.n;
  const std::uint8_t* active = out.begin(s) ? s.active : nullptr;
  const auto& nodes = tree_.nodes();
  if (nodes.empty()) return;
  if (active) mark_sinks(active);
  Criterion c;
  c.order = ex_->order();
  c.inv_theta = theta > 0.0 ? 1.0 / std::min(theta, 1.0) : 1e300;  // theta = 0: every pair summed
  c.kernel = kernel_softened(law.kind);
  c.support = c.kernel ? law.kernel->support() : 0.0;
  walked_.resize(n);
  if (theta > 0.0 && tol > 0.0) {
    // the estimate walk at theta = 1, no guard: the smallest |a| of each node, bottom up
    walk(law, c.inv_theta > 1.0 ? Criterion{1.0, c.support, 0.0, c.kernel, nullptr, c.order} : c, walked_);
    amin_.assign(nodes.size(), 1e300);
    for (std::size_t b = nodes.size(); b-- > 0;) {
      const TreeNode& nd = nodes[b];
      double m = 1e300;
      if (nd.n_child == 0) {
        for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q)
          m = std::min(m, std::sqrt(walked_.a[0][q] * walked_.a[0][q] + walked_.a[1][q] * walked_.a[1][q] +
                                    walked_.a[2][q] * walked_.a[2][q]));
      } else {
        for (std::uint32_t ch = nd.child; ch < nd.child + nd.n_child; ++ch) m = std::min(m, amin_[ch]);
      }
      amin_[b] = m;
    }
    c.amin = &amin_;
    c.tol = tol;
    out.pair_terms = walked_.pair_terms;
    out.node_terms = walked_.node_terms;
    walked_.resize(n);
  }
  walk(law, c, walked_, active != nullptr);  // the guard's estimate walk above: every particle
  add_from_tree_order(walked_, tree_.order(), G, out, active);
}

}  // namespace sph::gravity
