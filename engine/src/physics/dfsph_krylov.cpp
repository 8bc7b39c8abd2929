// DFSPH's pressure solves by BiCGStab (liquid.dfsph_solver = bicgstab; see dfsph_solver.h). Jacobi
// removes a pressure error that is smooth over the whole liquid (too high or too low everywhere) at a
// rate of (dx/H)^2 per iteration, so with a tolerance on the density error the tank's mid-depth pressure
// wandered by +-50% from step to step: a pressure off by dP compresses the column by only
// dt^2 dP / (rho0 H^2) in one step, 1e-4 for dP = 6 kPa in the 1 m tank at dt = 4 ms. A Krylov solve
// removes such an error in about H/dx iterations instead of (H/dx)^2.
//
// The system: the particles a Jacobi step would leave under pressure (the active set A: kappa + s alpha /
// dt^2 > 0, the primal-dual active set of Hintermueller, Ito & Kunisch 2002) take kappa + x_A with
// L_AA x_A = -s_A, where L x is the change of the sources s when kappa changes by x (walls follow the
// fluid linearly by their extrapolation) and is not symmetric because of the walls: hence BiCGStab (van
// der Vorst 1992, SIAM J. Sci. Stat. Comput. 13, 631), right-preconditioned by Jacobi's own diagonal,
// M^-1 = alpha/dt^2. Then kappa = max(0, kappa + x) on A and 0 off it is applied, a few Jacobi sweeps
// follow, and the active set is recomputed, until converged() (or, should the set cycle, Jacobi alone
// finishes). Every sum over particles is serial or a gather: the same result for any
// thread count.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/dfsph_solver.h"

namespace sph {
namespace {

/// Jacobi sweeps after each Krylov solve.
constexpr int kSweeps = 10;
/// Each Krylov solve reduces the error (mean and largest) by this factor, not further: the active set
/// changes after it, and its error with it.
constexpr double kInexact = 0.1;
/// When kStalls Krylov solves in a row (with their sweeps) leave the mean error above kProgress times
/// the least so far, the Krylov solves end and Jacobi sweeps finish: a particle whose pressure the solve
/// takes below zero and whose compression then brings it back makes the active set cycle (measured on
/// a jittered, swirling block at 1e-6).
constexpr double kProgress = 0.9;
constexpr int kStalls = 3;

/// Serial dot product over the first n entries: the same for any thread count.
double dot(const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

void DfsphSolver::op(const StageContext& c, const std::vector<double>& x, std::vector<double>& y, double dt) {
  const Particles& p = c.p;
  const std::size_t n = p.fluid(), nw = whyd_.size();
  const auto& rho = p[Field::Density];
  kwl_.resize(nw);
  for (auto& d : dv_) d.resize(n);
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t w = 0; w < nw; ++w) {  // the walls' kappa, linear in the fluid's (no clamp, no g term)
    double s = 0.0;
    for (std::size_t q = wstart_[w]; q < wstart_[w + 1]; ++q) s += wweight_[q] * x[wsrc_[q]];
    kwl_[w] = s;
  }
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t a = 0; a < n; ++a) {  // dv_a = -dt sum_b (x_a/rho_a + x_b/rho_b) g_ab
    double d[3];
    pressure_sum(a, x, kwl_, rho, n, d);
    for (int q = 0; q < 3; ++q) dv_[q][a] = q < p.dim() ? -dt * d[q] : 0.0;
  }
  const double* const v[3] = {dv_[0].data(), dv_[1].data(), dv_[2].data()};
#pragma omp parallel for schedule(static) if (threaded_)
  for (std::size_t a = 0; a < n; ++a) y[a] = act_[a] ? dt * divergence_of(a, v) : 0.0;
}

int DfsphSolver::bicgstab(const StageContext& c, double dt, double mean_tol, double max_tol, int budget) {
  const std::size_t n = c.p.fluid();
  const double rho0 = c.prm.liquid.rho0, dt2 = dt * dt;
  for (auto* v : {&x_, &r_, &rh_, &pv_, &ph_, &vv_, &sv_, &sh_, &tv_}) v->assign(n, 0.0);
  // r is the sources the linear model predicts after x, with the sign flipped: converged() on it
  auto small = [&](const std::vector<double>& r) {
    double sum = 0.0, worst = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      sum += std::abs(r[a]);
      worst = std::max(worst, std::abs(r[a]));
    }
    return sum / (rho0 * static_cast<double>(n)) <= mean_tol && worst / rho0 <= max_tol;
  };
  auto precondition = [&](const std::vector<double>& in, std::vector<double>& out) {
    for (std::size_t a = 0; a < n; ++a) out[a] = act_[a] ? alpha_[a] / dt2 * in[a] : 0.0;
  };
  r_ = b_;
  rh_ = b_;
  double rho_old = 1.0, alpha = 1.0, omega = 1.0;
  int ops = 0;
  while (ops + 2 <= budget && !small(r_)) {
    const double rho_new = dot(rh_, r_, n);
    if (rho_new == 0.0) break;  // breakdown: the outer loop restarts from the applied pressure
    const double beta = rho_new / rho_old * (alpha / omega);
    for (std::size_t a = 0; a < n; ++a) pv_[a] = r_[a] + beta * (pv_[a] - omega * vv_[a]);
    precondition(pv_, ph_);
    op(c, ph_, vv_, dt);
    ++ops;
    const double den = dot(rh_, vv_, n);
    if (den == 0.0) break;
    alpha = rho_new / den;
    for (std::size_t a = 0; a < n; ++a) sv_[a] = r_[a] - alpha * vv_[a];
    if (small(sv_)) {
      for (std::size_t a = 0; a < n; ++a) x_[a] += alpha * ph_[a];
      r_ = sv_;
      break;
    }
    precondition(sv_, sh_);
    op(c, sh_, tv_, dt);
    ++ops;
    const double tt = dot(tv_, tv_, n);
    omega = tt > 0.0 ? dot(tv_, sv_, n) / tt : 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      x_[a] += alpha * ph_[a] + omega * sh_[a];
      r_[a] = sv_[a] - omega * tv_[a];
    }
    if (omega == 0.0) break;
    rho_old = rho_new;
  }
  return ops;
}

int DfsphSolver::krylov(StageContext& c, std::vector<double>& total, double dt, const Target& t) {
  const std::size_t n = c.p.fluid();
  const int cap = c.prm.liquid.dfsph_max_iter;
  const double dt2 = dt * dt;
  wall_kappa(total, t.density, kw_);
  apply(c, total, kw_, dt);  // the warm start: the last step's pressure
  kappa_.resize(n); act_.resize(n); b_.resize(n);
  int ops = 0;
  bool done = converged(c, total, dt, t);
  double best = std::numeric_limits<double>::infinity();
  int stalls = 0;
  while (!done && ops < cap) {
    if (last_mean_ < kProgress * best) {
      best = last_mean_;
      stalls = 0;
    } else if (++stalls >= kStalls) {  // the active set cycles: Jacobi alone, which converges where it can
      return ops + sweeps(c, total, dt, t, cap - ops, done);
    }
    for (std::size_t a = 0; a < n; ++a) {  // res_ = -inf: no pressure at a (not in the divergence solve)
      act_[a] = std::isfinite(res_[a]) && alpha_[a] > 0.0 && total[a] + res_[a] * alpha_[a] / dt2 > 0.0;
      b_[a] = act_[a] ? -res_[a] : 0.0;
    }
    // inexact: a tenth of the error the clamp and the active set will leave anyway, not below the tolerance
    const int used = bicgstab(c, dt, std::max(t.tol, kInexact * last_mean_),
                              std::max(kMaxShare * t.tol, kInexact * last_max_), std::max(2, cap - ops));
    ops += used;
    for (std::size_t a = 0; a < n; ++a) {
      const double next = act_[a] ? std::max(0.0, total[a] + x_[a]) : 0.0;  // no pressure off the active set
      kappa_[a] = next - total[a];
      total[a] = next;
    }
    apply_change(c, total, t.density, dt);
    // Jacobi sweeps settle the particles where the clamp changed the set (a local error, which they
    // remove quickly): without them the active set cycled on a jittered, swirling block
    ops += 1 + sweeps(c, total, dt, t, kSweeps, done);
  }
  return ops;
}

}  // namespace sph
