// The leaf sums of the fast multipole method (gravity/fmm.h): a sink leaf's pair sums with the leaves
// it is not separated from, the multipoles it takes at each particle (M2P), and its local expansion at
// its particles (L2P), in that order.
#include <algorithm>
#include <cmath>

#include "gravity/fmm.h"
#include "gravity/fmm_walk.h"

namespace sph::gravity {
namespace {

/// The Plummer pair sums of sinks 0..cnt-1 from one source particle (a sink `self` is that particle):
/// one lane per sink, each sink's sum in source order, so the same bits for any vector width.
void p2p_plummer(std::ptrdiff_t cnt, const double* __restrict x, const double* __restrict y,
                 const double* __restrict z, double xj, double yj, double zj, double mj, double e2, std::ptrdiff_t self,
                 double* __restrict ax, double* __restrict ay, double* __restrict az, double* __restrict ph,
                 double* __restrict re2, double* __restrict mmax) {
  for (std::ptrdiff_t i = 0; i < cnt; ++i) {
    const bool me = i == self;
    const double dx = x[i] - xj, dy = y[i] - yj, dz = z[i] - zj;
    const double s = me ? 1.0 : dx * dx + dy * dy + dz * dz + e2;
    const double inv = 1.0 / std::sqrt(s), m = me ? 0.0 : mj, mf = m * inv * inv * inv;
    ax[i] -= mf * dx;
    ay[i] -= mf * dy;
    az[i] -= mf * dz;
    ph[i] -= m * inv;
    re2[i] = std::min(re2[i], me ? 1e300 : s);
    mmax[i] = std::max(mmax[i], m);
  }
}


}  // namespace

void FastMultipole::leaf(std::uint32_t b, const std::vector<std::uint32_t>& near, Walk& w) const {
  const auto& nodes = tree_.nodes();
  const TreeNode& nb = nodes[b];
  const std::size_t first = nb.first, count = nb.count;
  // the sinks: every particle of the leaf, or (individual time steps) its active ones, gathered; each
  // sink's sums are the same either way
  const bool some = w.live && live_[b] < count;
  std::size_t cnt = count;
  const double *x = tx()[0].data() + first, *y = tx()[1].data() + first, *z = tx()[2].data() + first;
  if (some) {
    w.slot.clear();
    w.local.assign(count, -1);
    for (std::size_t i = 0; i < count; ++i)
      if (sink_[first + i]) {
        w.local[i] = static_cast<std::ptrdiff_t>(w.slot.size());
        w.slot.push_back(static_cast<std::uint32_t>(i));
      }
    cnt = w.slot.size();
    for (int k = 0; k < 3; ++k) {
      w.sx[k].resize(cnt);
      for (std::size_t i = 0; i < cnt; ++i) w.sx[k][i] = tx()[k][first + w.slot[i]];
    }
    x = w.sx[0].data(), y = w.sx[1].data(), z = w.sx[2].data();
  }
  const auto tree_slot = [&](std::size_t i) { return first + (some ? w.slot[i] : i); };
  for (auto* v : {&w.ax, &w.ay, &w.az, &w.phi, &w.mmax}) v->assign(cnt, 0.0);
  w.re2.assign(cnt, 1e300);
  double *ax = w.ax.data(), *ay = w.ay.data(), *az = w.az.data(), *ph = w.phi.data(), *re2 = w.re2.data(),
         *mmax = w.mmax.data();
  const PairLaw& law = *w.law;
  const bool plummer = law.kind == Softening::Plummer;
  const double e2 = law.eps2;
  for (const std::uint32_t a : near) {
    const TreeNode& na = nodes[a];
    for (std::size_t j = na.first; j < na.first + na.count; ++j) {
      const double xj = tx()[0][j], yj = tx()[1][j], zj = tx()[2][j], mj = tm()[j], hj = th()[j];
      if (plummer) {
        std::ptrdiff_t self = j >= first && j < first + count ? static_cast<std::ptrdiff_t>(j - first) : -1;
        if (some && self >= 0) self = w.local[static_cast<std::size_t>(self)];
        p2p_plummer(static_cast<std::ptrdiff_t>(cnt), x, y, z, xj, yj, zj, mj, e2, self, ax, ay, az, ph, re2, mmax);
      } else {
        for (std::size_t i = 0; i < cnt; ++i) {
          const std::size_t ti = tree_slot(i);
          if (ti == j) continue;
          const double dx = x[i] - xj, dy = y[i] - yj, dz = z[i] - zj, r2 = dx * dx + dy * dy + dz * dz;
          const double hi = th()[ti];
          double f, p;
          law(r2, hi, hj, f, p);
          ax[i] -= mj * f * dx;
          ay[i] -= mj * f * dy;
          az[i] -= mj * f * dz;
          ph[i] += mj * p;
          re2[i] = std::min(re2[i], r2 + law.soft2(hi, hj));
          mmax[i] = std::max(mmax[i], mj);
        }
      }
    }
    w.counts.pairs += na.count * cnt;
  }
  for (const std::uint32_t a : w.direct) {  // four sinks at a time (the same bits as one by one)
    const TreeNode& na = nodes[a];
    std::size_t i = 0;
    for (; i + 4 <= cnt; i += 4) {
      double R[4][3];
      for (std::size_t v = 0; v < 4; ++v) {
        R[v][0] = x[i + v] - na.com[0];
        R[v][1] = y[i + v] - na.com[1];
        R[v][2] = z[i + v] - na.com[2];
      }
      ex_->m2p4(M(a), R, w.e2, ph + i, ax + i, ay + i, az + i);
    }
    for (; i < cnt; ++i)
      ex_->m2p(M(a), x[i] - na.com[0], y[i] - na.com[1], z[i] - na.com[2], w.e2, ph[i], ax[i], ay[i], az[i]);
    w.counts.m2l += cnt;
  }
  Result& out = *w.out;
  for (std::size_t i = 0; i < cnt; ++i) {
    double p = ph[i], gx = ax[i], gy = ay[i], gz = az[i];
    ex_->l2p(L(b), x[i] - nb.com[0], y[i] - nb.com[1], z[i] - nb.com[2], p, gx, gy, gz);
    const std::size_t t = tree_slot(i);
    out.a[0][t] = gx;
    out.a[1][t] = gy;
    out.a[2][t] = gz;
    out.phi[t] = p;
    out.t2_pair[t] = mmax[i] > 0.0 ? re2[i] * std::sqrt(re2[i]) / (tm()[t] + mmax[i]) : 1e300;
  }
}

}  // namespace sph::gravity
