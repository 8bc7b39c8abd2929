// DFSPH's pressure solves: see dfsph_solver.h (Bender & Koschier 2017, Algorithms 2 and 3).
#include "physics/dfsph_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/parallel.h"
#include "physics/dfsph_relaxation.h"
#include "sph/kernel_shapes.h"

namespace sph {
namespace {

/// Fluid particles with fewer neighbours than this share of a full kernel's (the free surface) are left
/// out of the divergence solve, as in SPlisHSPlasH (20 of 33 in 3D, 7 of 13 in 2D).
constexpr double kFullShare = 0.6;

/// Serial sum and maximum of the first n entries: the same for any thread count.
std::pair<double, double> sum_max(const std::vector<double>& e, std::size_t n) {
  double s = 0.0, m = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    s += e[a];
    m = std::max(m, e[a]);
  }
  return {s, m};
}

}  // namespace

void DfsphSolver::prepare(const StageContext& c) {
  const Particles& p = c.p;
  const std::size_t n = p.fluid(), real = p.size();
  const auto& h = p[Field::H];
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const double support = c.kernel.support();
  // the neighbour count of a full kernel on the scene's lattice: pi R^2 / dx^2, 4/3 pi R^3 / dx^3
  const double R = support * (n ? h[0] : 0.0), dx = c.spacing > 0.0 ? c.spacing : 1.0;
  const double full = p.dim() == 3 ? 4.0 / 3.0 * std::numbers::pi * std::pow(R / dx, 3)
                                   : p.dim() == 2 ? std::numbers::pi * (R / dx) * (R / dx) : 2.0 * R / dx;
  auto within = [&](std::size_t a, std::uint32_t b, double r[3]) {
    for (int k = 0; k < 3; ++k) r[k] = p.x[k][a] - p.x[k][b];
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    const double hab = 0.5 * (h[a] + h[b]);
    return r2 > 0.0 && r2 < support * support * hab * hab;
  };
  threaded_ = real >= kParallelMin;  // as the force loops: fluid and walls together make the work
  start_.assign(n + 1, 0);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t k = 0;
    double r[3];
    for (std::uint32_t b : c.nl.of(a)) k += within(a, b, r) ? 1 : 0;
    start_[a + 1] = k;
  }
  for (std::size_t a = 0; a < n; ++a) start_[a + 1] += start_[a];
  const std::size_t np = start_[n];
  src_.resize(np); flip_.resize(np); wall_.resize(np); gx_.resize(np); gy_.resize(np); gz_.resize(np);
  alpha_.resize(n); full_.resize(n);
  const double sigma = c.kernel.sigma();
  const int d = p.dim();
  // the kernel's shape chosen once for the loop, not per pair (sph/kernel_shapes.h)
  shape::with_shape(c.kernel.type(), d, [&](auto shp) {
#pragma omp parallel for schedule(static) if (threaded_)
    for (std::size_t a = 0; a < n; ++a) {
      std::size_t k = start_[a];
      double sx = 0.0, sy = 0.0, sz = 0.0, s2 = 0.0, r[3];
      for (std::uint32_t b : c.nl.of(a)) {
        if (!within(a, b, r)) continue;
        const bool ghost = b >= real;
        const std::uint32_t s = ghost ? p.ghost_src[b - real] : b;
        const double dist = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        const double hinv = 2.0 / (h[a] + h[b]);
        double hd1 = hinv * hinv;  // 1/h^(d+1)
        for (int q = 1; q < d; ++q) hd1 *= hinv;
        const double f = m[s] * sigma * hd1 * shp.dw(dist * hinv) / dist;  // m_b dW/dr / r
        src_[k] = s;
        flip_[k] = ghost ? p.ghost_flip[b - real] : 0;
        wall_[k] = p.kind[b] != 0;
        gx_[k] = f * r[0]; gy_[k] = f * r[1]; gz_[k] = f * r[2];
        sx += gx_[k]; sy += gy_[k]; sz += gz_[k];
        if (!wall_[k]) s2 += gx_[k] * gx_[k] + gy_[k] * gy_[k] + gz_[k] * gz_[k];
        ++k;
      }
      const double den = sx * sx + sy * sy + sz * sz + s2;
      alpha_[a] = den > 1e-12 * rho[a] * rho[a] / (dx * dx) ? rho[a] / den : 0.0;  // a lone particle: no solve
      full_[a] = static_cast<double>(k - start_[a]) >= kFullShare * full ? 1 : 0;
    }
  });
  prepare_walls(c);
  // the sweeps' relaxation for this kernel and eta (a pure function of them: recomputed only when they change)
  if (c.kernel.type() != relax_kernel_ || d != relax_dim_ || c.eta != relax_eta_) {
    relax_kernel_ = c.kernel.type();
    relax_dim_ = d;
    relax_eta_ = c.eta;
    relax_ = dfsph_relaxation(c.kernel, c.eta);
  }
}

double DfsphSolver::divergence_of(std::size_t a, const double* const v[3]) const {
  double d = 0.0;
  for (std::size_t k = start_[a]; k < start_[a + 1]; ++k) {
    double w[3] = {v[0][a], v[1][a], v[2][a]};
    if (!wall_[k]) {
      const std::uint32_t s = src_[k];
      for (int q = 0; q < 3; ++q) w[q] -= (flip_[k] >> q & 1u) ? -v[q][s] : v[q][s];
    }
    d += w[0] * gx_[k] + w[1] * gy_[k] + w[2] * gz_[k];
  }
  return d;
}

double DfsphSolver::source(const StageContext& c, const Target& t, std::size_t a, double dt) const {
  const double* const v[3] = {c.p.v[0].data(), c.p.v[1].data(), c.p.v[2].data()};
  if (t.density) return c.p[Field::Density][a] + dt * divergence_of(a, v) - c.prm.liquid.rho0;
  return full_[a] ? dt * divergence_of(a, v) : -std::numeric_limits<double>::infinity();
}

void DfsphSolver::pressure_sum(std::size_t a, const std::vector<double>& k, const std::vector<double>& kw,
                               const std::vector<double>& rho, std::size_t n, double out[3]) const {
  const double ka = k[a] / rho[a];
  out[0] = out[1] = out[2] = 0.0;
  for (std::size_t q = start_[a]; q < start_[a + 1]; ++q) {
    const std::uint32_t s = src_[q];
    const double f = ka + (wall_[q] ? kw[s - n] : k[s]) / rho[s];
    out[0] += f * gx_[q]; out[1] += f * gy_[q]; out[2] += f * gz_[q];
  }
}

void DfsphSolver::apply(StageContext& c, const std::vector<double>& kap, const std::vector<double>& kw,
                        double dt) const {
  Particles& p = c.p;
  const std::size_t n = p.fluid();
  const auto& rho = p[Field::Density];
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t a = 0; a < n; ++a) {
    double dv[3];
    pressure_sum(a, kap, kw, rho, n, dv);
    for (int q = 0; q < p.dim(); ++q) p.v[q][a] -= dt * dv[q];
  }
}

void DfsphSolver::apply_change(StageContext& c, const std::vector<double>& total, bool hydrostatic, double dt) {
  wall_kappa(total, hydrostatic, kw_new_);
  for (std::size_t w = 0; w < kw_.size(); ++w) {  // kw_new_ becomes the walls' change
    const double next = kw_new_[w];
    kw_new_[w] = next - kw_[w];
    kw_[w] = next;
  }
  apply(c, kappa_, kw_new_, dt);
}

bool DfsphSolver::converged(const StageContext& c, const std::vector<double>& total, double dt, const Target& t) {
  const std::size_t n = c.p.fluid();
  const double rho0 = c.prm.liquid.rho0;
  res_.resize(n); err_.resize(n);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t a = 0; a < n; ++a) {
    res_[a] = source(c, t, a, dt);
    // compression, or a pressure where there is none (s < 0 with kappa > 0: a warm start that pushes
    // too hard, e.g. after a short step, would otherwise stay and fling particles apart)
    err_[a] = (total[a] > 0.0 ? std::abs(res_[a]) : std::max(0.0, res_[a])) / rho0;
  }
  const auto [sum, worst] = sum_max(err_, n);
  last_mean_ = n ? sum / static_cast<double>(n) : 0.0;
  last_max_ = worst;
  return last_mean_ <= t.tol && last_max_ <= kMaxShare * t.tol;
}

int DfsphSolver::sweeps(StageContext& c, std::vector<double>& total, double dt, const Target& t, int count,
                        bool& done) {
  const std::size_t n = c.p.fluid();
  kappa_.resize(n);
  const double relax = relax_;
  int it = 0;
  while (!(done = converged(c, total, dt, t)) && it < count) {
#pragma omp parallel for schedule(static) if (threaded_)
    for (std::size_t a = 0; a < n; ++a)  // res_ = -inf (no pressure at a) gives kappa = 0
      kappa_[a] = std::max(0.0, total[a] + relax * res_[a] * alpha_[a] / (dt * dt)) - total[a];
    for (std::size_t a = 0; a < n; ++a) total[a] += kappa_[a];
    apply_change(c, total, t.density, dt);
    ++it;
  }
  return it;
}

int DfsphSolver::jacobi(StageContext& c, std::vector<double>& total, double dt, const Target& t) {
  wall_kappa(total, t.density, kw_);
  apply(c, total, kw_, dt);  // the warm start: the last step's pressure
  bool done = false;
  return sweeps(c, total, dt, t, c.prm.liquid.dfsph_max_iter, done);
}

int DfsphSolver::divergence(StageContext& c, double dt) {
  auto& kv = c.p[Field::DfsphKappaV];  // the last step's dt kappa_v [length^2/time]: its kappa in this step
  for (std::size_t a = 0; a < c.p.fluid(); ++a) kv[a] = full_[a] ? kv[a] / dt : 0.0;  // no pressure where not full
  // the source is dt Drho/Dt, compared with rho0 as the density's
  const Target t{false, c.prm.liquid.dfsph_eta_div};
  const int it = c.prm.liquid.dfsph_solver == DfsphSolverType::Jacobi ? jacobi(c, kv, dt, t) : krylov(c, kv, dt, t);
  kw_div_ = kw_;
  return it;
}

int DfsphSolver::density(StageContext& c, double dt, ProjectionStats& stats) {
  const Target t{true, c.prm.liquid.dfsph_eta};
  auto& k = c.p[Field::DfsphKappa];
  const int it = c.prm.liquid.dfsph_solver == DfsphSolverType::Jacobi ? jacobi(c, k, dt, t) : krylov(c, k, dt, t);
  stats.density_error = last_mean_;
  stats.density_error_max = last_max_;
  return it;
}

void DfsphSolver::finish(StageContext& c, double dt) const {
  Particles& p = c.p;
  const auto& rho = p[Field::Density];
  const auto& k = p[Field::DfsphKappa];
  auto& kv = p[Field::DfsphKappaV];
  auto& P = p[Field::Pressure];
  for (std::size_t a = 0; a < p.fluid(); ++a) {
    P[a] = rho[a] * (k[a] + kv[a]);
    kv[a] *= dt;
  }
  // the walls' pressure, extrapolated from the fluid's as in both solves: what a sensor on a wall reads
  for (std::size_t w = 0; w < kw_.size(); ++w)
    P[p.fluid() + w] = rho[p.fluid() + w] * (kw_[w] + (w < kw_div_.size() ? kw_div_[w] : 0.0));
}

}  // namespace sph
