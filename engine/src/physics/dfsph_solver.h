// DFSPH's two pressure solves (Bender & Koschier 2017, IEEE TVCG 23, 1193, Algorithms 2 and 3) over the
// fluid of one state: pair gradients and the stiffness factors alpha once, then Jacobi iterations on
// the velocities. With g_ab = m_b grad W_ab (h_ab = (h_a + h_b)/2) and kappa = P/rho [length^2/time^2]:
//   alpha_a = rho_a / (|sum_b g_ab|^2 + sum_{b fluid} |g_ab|^2)                      (their eq. 11)
//   density:    source_a = rho_a + dt sum_b (v_a - v_b) . g_ab - rho0                  (predicted compression)
//   divergence: source_a = dt sum_b (v_a - v_b) . g_ab                                  (dt Drho/Dt)
//   kappa_a <- max(0, kappa_a + w source_a alpha_a / dt^2) (relaxed Jacobi: w from the kernel's width, at
//   most 1/2 in 2D and 0.3 in 3D, physics/dfsph_relaxation.h),
//   v_a -= dt sum_b (kappa_a/rho_a + kappa_b/rho_b) g_ab for the change of kappa.
// kappa >= 0 (projected Jacobi: a liquid takes no tension), so a free surface's particles, whose
// summation density is below rho0, stay free; a solve ends when the mean of the compression (and of the
// expansion where kappa > 0) over the fluid is below its tolerance. Wall particles take the pressure of
// the fluid around them, as Adami et al.'s dummy particles (2012, JCP 231, 7057, eq. 27):
//   kappa_w = max(0, sum_f kappa_f W_wf / sum_f W_wf + g . sum_f (x_w - x_f) W_wf / sum_f W_wf),
// the second term (the hydrostatic one) in the density solve only. The step's kappa is the next step's
// warm start (see finish()), and P = rho (kappa + kappa_v) is the step's pressure. Gathers in list order:
// the same result for any thread count. liquid.dfsph_solver = bicgstab solves the same system by
// BiCGStab on the particles under pressure instead (dfsph_krylov.cpp), for tight tolerances.
#pragma once
#include <cstdint>
#include <vector>

#include "core/stage.h"

namespace sph {

class DfsphSolver {
 public:
  /// Pairs within the support, alpha and the walls' weights for the current positions and densities.
  void prepare(const StageContext& c);
  /// Makes the velocity field divergence-free where the kernel is full (Algorithm 3). Returns iterations.
  int divergence(StageContext& c, double dt);
  /// Corrects the predicted velocities so that the step keeps rho0 (Algorithm 2). Returns iterations;
  /// the mean and largest error at its end in `stats`.
  int density(StageContext& c, double dt, ProjectionStats& stats);
  /// After both solves: P = rho (kappa + kappa_v) [pressure], what both exerted in the step (on the walls
  /// too, from their extrapolated kappa, for wall sensors; the forces do not use it); and the
  /// divergence solve's warm start kept as dt kappa_v: its pressure removes a velocity divergence within
  /// one step, so it scales as 1/dt
  /// (a warm start after a sliver of a step, e.g. one landing on an output time, would otherwise kick
  /// the next step by the ratio of the steps).
  void finish(StageContext& c, double dt) const;

 private:
  /// A solve also iterates until no particle's error exceeds this many times the tolerance on the mean: a
  /// pressure too low everywhere compresses only the bottom rows, which the mean hardly sees (the tank's
  /// pressure swung between 0.4 and 2.2 times the hydrostatic one with the mean alone).
  static constexpr double kMaxShare = 20.0;
  /// What a solve drives to zero at fluid a: the predicted compression rho_a + dt sum_b (v_a - v_b) . g_ab
  /// - rho0 (density; the walls' kappa then has its hydrostatic term), or dt sum_b (v_a - v_b) . g_ab
  /// where the kernel is full (-inf elsewhere: no pressure there). Both [density].
  struct Target {
    bool density;
    double tol;  ///< mean error at which the solve stops [dimensionless]
  };
  double source(const StageContext& c, const Target& t, std::size_t a, double dt) const;
  /// Sources into res_ and errors into err_ for the pressure `total`; the mean and largest error into
  /// last_mean_ and last_max_. True when both are within the tolerance.
  bool converged(const StageContext& c, const std::vector<double>& total, double dt, const Target& t);
  /// From the warm start `total` (applied first) until converged(): projected Jacobi (liquid.dfsph_solver
  /// = jacobi) or BiCGStab on the particles under pressure (bicgstab, dfsph_krylov.cpp). Returns
  /// the applications of the pressure operator.
  int jacobi(StageContext& c, std::vector<double>& total, double dt, const Target& t);
  /// At most `count` projected Jacobi sweeps, fewer if converged() first (then `done`). Returns the sweeps.
  int sweeps(StageContext& c, std::vector<double>& total, double dt, const Target& t, int count, bool& done);
  int krylov(StageContext& c, std::vector<double>& total, double dt, const Target& t);
  /// BiCGStab on the linear system of the active particles, rhs in b_, solution in x_, until the mean and
  /// largest residual are within the tolerances [dimensionless] or `budget` operations (dfsph_krylov.cpp).
  int bicgstab(const StageContext& c, double dt, double mean_tol, double max_tol, int budget);
  /// y = L x: the change of the sources when kappa changes by x on the active particles (walls linear in
  /// the fluid's kappa), y = 0 on the others (dfsph_krylov.cpp).
  void op(const StageContext& c, const std::vector<double>& x, std::vector<double>& y, double dt);
  /// The walls' fluid neighbours, weights and hydrostatic terms (dfsph_walls.cpp).
  void prepare_walls(const StageContext& c);
  /// The walls' kappa from the fluid's `k` (Adami's extrapolation), into `out` (one per wall particle).
  void wall_kappa(const std::vector<double>& k, bool hydrostatic, std::vector<double>& out) const;
  /// out = sum_b (k_a/rho_a + k_b/rho_b) g_ab of fluid a, k_b = kw[b - n] for a wall (n fluid particles).
  void pressure_sum(std::size_t a, const std::vector<double>& k, const std::vector<double>& kw,
                    const std::vector<double>& rho, std::size_t n, double out[3]) const;
  /// v_a -= dt sum_b (k_a/rho_a + k_b/rho_b) g_ab for every fluid a, k_b = kw[b - fluid] for a wall.
  void apply(StageContext& c, const std::vector<double>& k, const std::vector<double>& kw, double dt) const;
  /// Applies the change of `total` to kappa_ and the walls' to kw_ (kept in step with `total`).
  void apply_change(StageContext& c, const std::vector<double>& total, bool hydrostatic, double dt);
  /// sum_b (v_a - v_b) . g_ab of fluid a for the velocities v[0..2] of the fluid (walls at rest; a ghost's
  /// from its source, mirrored) [density/time].
  double divergence_of(std::size_t a, const double* const v[3]) const;

  std::vector<std::size_t> start_;     ///< pairs of fluid a: [start_[a], start_[a + 1])
  std::vector<std::uint32_t> src_;     ///< the neighbour's real index (a ghost's source)
  std::vector<std::uint8_t> flip_;     ///< a ghost's mirror bits: its velocity components that flip
  std::vector<std::uint8_t> wall_;     ///< 1: a wall particle (at rest)
  std::vector<double> gx_, gy_, gz_;   ///< g_ab = m_b grad W_ab [mass/length^(d+1)]
  std::vector<double> alpha_;          ///< per fluid particle [length^2/density]
  std::vector<std::uint8_t> full_;     ///< 1: the kernel is full (the divergence solve constrains it)
  std::vector<std::size_t> wstart_;    ///< fluid neighbours of wall w: [wstart_[w], wstart_[w + 1])
  std::vector<std::uint32_t> wsrc_;    ///< that fluid particle (a ghost's source)
  std::vector<double> wweight_;        ///< W_wf / sum_f W_wf [dimensionless]
  std::vector<double> whyd_;           ///< g . sum_f (x_w - x_f) W_wf / sum_f W_wf per wall [length^2/time^2]
  std::vector<double> kappa_, err_, res_, kw_, kw_new_;  ///< per-iteration scratch
  std::vector<double> kw_div_;  ///< the walls' kappa at the end of the divergence solve (finish() adds it to P)
  std::vector<std::uint8_t> act_;  ///< 1: in the Krylov solve's linear system (under pressure or compressed)
  std::vector<double> x_, b_, r_, rh_, pv_, ph_, vv_, sv_, sh_, tv_, dv_[3], kwl_;  ///< BiCGStab's vectors
  bool threaded_ = false;                           ///< loops in a thread team (core/parallel.h)
  double relax_ = 0.5;                              ///< the sweeps' relaxation w (dfsph_relaxation.h)
  KernelType relax_kernel_ = KernelType::M4;        ///< the kernel, dimension and eta relax_ is for
  int relax_dim_ = 0;
  double relax_eta_ = 0.0;
  double last_mean_ = 0.0, last_max_ = 0.0;         ///< the last solve's mean and largest error [dimensionless]
};

}  // namespace sph
