// Walking the Barnes-Hut tree (gravity/barnes_hut.h): the opening criterion, the multipole field of a
// cell used whole, the per-target walks of evaluate() and the cells one particle's walk takes.
#include "gravity/barnes_hut.h"

#include <algorithm>
#include <cmath>

namespace sph::gravity {

void multipole_field(const TreeNode& nd, double dx, double dy, double dz, double e2, double& ax, double& ay,
                     double& az, double& phi) {
  // phi = -[M g + 1/2 S_jk d_j d_k g], g = (r^2 + e2)^(-1/2), a = -grad phi (per unit G):
  // a = -M x s^-3 + 3 S x s^-5 + 3/2 tr(S) x s^-5 - 15/2 (x.S.x) x s^-7, s^2 = r^2 + e2
  const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz + e2), inv2 = inv * inv, inv3 = inv * inv2,
               inv5 = inv3 * inv2;
  const double* S = nd.S;
  const double Sx = S[0] * dx + S[1] * dy + S[2] * dz, Sy = S[1] * dx + S[3] * dy + S[4] * dz,
               Sz = S[2] * dx + S[4] * dy + S[5] * dz;
  const double xSx = dx * Sx + dy * Sy + dz * Sz, tr = S[0] + S[3] + S[5];
  const double c = -nd.mass * inv3 - 7.5 * xSx * inv5 * inv2 + 1.5 * tr * inv5;
  ax += c * dx + 3.0 * inv5 * Sx;
  ay += c * dy + 3.0 * inv5 * Sy;
  az += c * dz + 3.0 * inv5 * Sz;
  phi -= nd.mass * inv + 0.5 * (3.0 * xSx * inv5 - tr * inv3);
}

BarnesHutTree::Opening BarnesHutTree::opening(const PairLaw& law, double theta) const {
  Opening op;
  op.theta = theta;
  op.inv_theta = theta > 0.0 ? 1.0 / theta : 0.0;
  op.kernel = kernel_softened(law.kind);
  op.support = op.kernel ? law.kernel->support() : 0.0;
  return op;
}

template <class OnCell, class OnLeaf>
void BarnesHutTree::visit(std::size_t t, const Opening& op, double allowed, std::vector<std::uint32_t>& stack,
                          OnCell&& on_cell, OnLeaf&& on_leaf) const {
  const double xi = sx_[0][t], yi = sx_[1][t], zi = sx_[2][t], hi = sh_[t];
  stack.clear();
  stack.push_back(0);
  while (!stack.empty()) {
    const std::uint32_t node = stack.back();
    const TreeNode& nd = nodes_[node];
    stack.pop_back();
    const double dx = xi - nd.com[0], dy = yi - nd.com[1], dz = zi - nd.com[2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    // Barnes 1994: d > l/theta + delta, l the cell's side, delta the offset of its centre of mass
    const double open = 2.0 * nd.half * op.inv_theta + nd.delta;
    bool use = op.theta > 0.0 && d2 > open * open && nd.bmax * nd.bmax < d2;
    if (use && allowed < 1e300) {
      // the size of the octupole term the expansion drops, M bmax^3 / d^5, within tol |a_i|
      const double b3 = nd.bmax * nd.bmax * nd.bmax;
      use = nd.mass * b3 <= allowed * d2 * d2 * std::sqrt(d2);
    }
    if (use && op.kernel) {
      const double reach = nd.bmax + op.support * std::max(hi, nd.hmax);
      use = d2 > reach * reach;
    }
    if (use) {
      on_cell(node, nd, dx, dy, dz);
    } else if (nd.n_child > 0) {
      for (std::uint32_t ch = nd.child + nd.n_child; ch-- > nd.child;) stack.push_back(ch);
    } else {
      on_leaf(node, nd);
    }
  }
}

void BarnesHutTree::walk(const Sources& s, const PairLaw& law, double theta, const Guard& guard, Result& out,
                         const std::uint8_t* active) const {
  const std::size_t n = s.n;
  const Opening op = opening(law, theta);
  const double e2 = op.kernel ? 0.0 : law.eps2;  // softening of the multipoles (kernel: cells are beyond it)
  std::size_t pairs = 0, cells = 0;
#pragma omp parallel reduction(+ : pairs, cells) if (n >= 512)
  {
    std::vector<std::uint32_t> stack;
    stack.reserve(512);
#pragma omp for schedule(dynamic, 64)
    for (std::size_t t = 0; t < n; ++t) {  // targets in tree order
      if (active && !active[order_[t]]) continue;  // not a sink: its results are kept from before
      const double xi = sx_[0][t], yi = sx_[1][t], zi = sx_[2][t], hi = sh_[t], mi = sm_[t];
      // the cell-error bound this target tolerates (per unit G): tol |a_i|, |a_i| from the estimate pass
      const double allowed = guard.a_est ? guard.tol * (*guard.a_est)[t] : 1e300;
      double ax = 0.0, ay = 0.0, az = 0.0, phi = 0.0, re2_min = 1e300, msum_max = 0.0;
      visit(
          t, op, allowed, stack,
          [&](std::uint32_t, const TreeNode& nd, double dx, double dy, double dz) {
            multipole_field(nd, dx, dy, dz, e2, ax, ay, az, phi);
            ++cells;
          },
          [&](std::uint32_t, const TreeNode& nd) {
            for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {  // a leaf: pair by pair
              if (q == t) continue;
              const double px = xi - sx_[0][q], py = yi - sx_[1][q], pz = zi - sx_[2][q];
              const double r2 = px * px + py * py + pz * pz;
              double f, p;
              law(r2, hi, sh_[q], f, p);
              const double mf = sm_[q] * f;
              ax -= mf * px;
              ay -= mf * py;
              az -= mf * pz;
              phi += sm_[q] * p;
              re2_min = std::min(re2_min, r2 + law.soft2(hi, sh_[q]));
              msum_max = std::max(msum_max, sm_[q]);
              ++pairs;
            }
          });
      out.a[0][t] = ax;
      out.a[1][t] = ay;
      out.a[2][t] = az;
      out.phi[t] = phi;
      // a lower bound of min_j r_eff^3 / (m_i + m_j) without a division per pair (per unit G)
      out.t2_pair[t] = msum_max > 0.0 ? re2_min * std::sqrt(re2_min) / (mi + msum_max) : 1e300;
    }
  }
  out.pair_terms += pairs;
  out.node_terms += cells;
}

std::vector<CellUse> BarnesHutTree::interactions(const Sources& s, const PairLaw& law, double theta, double tol,
                                                 std::size_t i) const {
  std::vector<CellUse> used;
  if (nodes_.empty() || i >= s.n) return used;
  const auto t = static_cast<std::size_t>(std::find(order_.begin(), order_.end(), i) - order_.begin());
  std::vector<std::uint32_t> stack;
  double allowed = 1e300;
  if (theta > 0.0 && tol > 0.0) {  // the estimate pass for this target alone, as evaluate() does
    double a[3] = {0, 0, 0}, phi = 0.0;
    const double e2 = kernel_softened(law.kind) ? 0.0 : law.eps2;
    visit(
        t, opening(law, kEstimateTheta), 1e300, stack,
        [&](std::uint32_t, const TreeNode& nd, double dx, double dy, double dz) {
          multipole_field(nd, dx, dy, dz, e2, a[0], a[1], a[2], phi);
        },
        [&](std::uint32_t, const TreeNode& nd) {
          for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {
            if (q == t) continue;
            const double px = sx_[0][t] - sx_[0][q], py = sx_[1][t] - sx_[1][q], pz = sx_[2][t] - sx_[2][q];
            double f, p;
            law(px * px + py * py + pz * pz, sh_[t], sh_[q], f, p);
            a[0] -= sm_[q] * f * px;
            a[1] -= sm_[q] * f * py;
            a[2] -= sm_[q] * f * pz;
          }
        });
    allowed = tol * std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }
  visit(
      t, opening(law, theta), allowed, stack,
      [&](std::uint32_t node, const TreeNode&, double, double, double) { used.push_back({node, true}); },
      [&](std::uint32_t node, const TreeNode&) { used.push_back({node, false}); });
  return used;
}

void BarnesHutTree::evaluate(const Sources& s, const PairLaw& law, double G, double theta, Result& out,
                             double tol) const {
  const std::size_t n = s.n;
  const std::uint8_t* active = out.begin(s) ? s.active : nullptr;
  if (nodes_.empty()) return;
  walked_.resize(n);
  Guard guard;
  if (theta > 0.0 && tol > 0.0) {
    // the estimate pass: |a_i| at the coarse opening angle kEstimateTheta, for the relative guard
    walk(s, law, kEstimateTheta, guard, walked_, active);
    a_est_.resize(n);
    for (std::size_t t = 0; t < n; ++t)
      a_est_[t] = std::sqrt(walked_.a[0][t] * walked_.a[0][t] + walked_.a[1][t] * walked_.a[1][t] +
                            walked_.a[2][t] * walked_.a[2][t]);
    guard.a_est = &a_est_;
    guard.tol = tol;
    out.pair_terms = walked_.pair_terms;
    out.node_terms = walked_.node_terms;
    walked_.resize(n);
  }
  walk(s, law, theta, guard, walked_, active);
  add_from_tree_order(walked_, order_, G, out, active);
}

}  // namespace sph::gravity
