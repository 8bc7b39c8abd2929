// Summation density (seed 000 eq. 3.2.17) or volume density 1/V_a = sum_b W_ab (seed 004), with h
// solved by Newton-Raphson on g(h) = rho(h) - m eta^d / h^d (seed 000 eq. 3.5.1, App. B) and a
// bisection fallback, or held fixed. Omega_a = 1 + h_a/(d rho_a) sum_b w_b dW_ab/dh (seed 000 eqs.
// 3.3.2, 3.3.4); Omega = 1 for fixed h.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "sph/kernel_shapes.h"
#include "sph/newton.h"

namespace sph {
namespace {

struct Sums {
  double rho = 0.0;   ///< sum_b w_b W(r_ab, h), w_b = m_b (mass) or m_a (volume)
  double drho = 0.0;  ///< sum_b w_b dW(r_ab, h)/dh
};

/// The pairs of one particle that the h solve can reach (r < support h_limit), gathered once: the Newton
/// iterations then sweep short contiguous arrays instead of the neighbour list and the positions.
struct Candidates {
  std::vector<double> r, w;   ///< distance [length] (squared while gathering) and weight w_b [mass]
  std::vector<double> tw, td;  ///< per-candidate terms of the two sums (scratch)
  std::size_t n = 0;
  void fit(std::size_t m) {
    if (r.size() >= m) return;
    const std::size_t cap = std::max<std::size_t>(2 * m, 64);
    r.resize(cap); w.resize(cap); tw.resize(cap); td.resize(cap);
  }
};

/// Volume: rho_a = m_a sum_b W_ab (every neighbour weighs m_a). SkipWalls: Lennard-Jones wall
/// particles are not in the sums.
template <bool Volume, bool SkipWalls>
void gather(const Particles& p, std::size_t i, std::span<const std::uint32_t> nb, const std::vector<double>& m,
            double reach2, Candidates& c) {
  c.fit(nb.size());
  const double xi = p.x[0][i], yi = p.x[1][i], zi = p.x[2][i];
  std::size_t n = 0;
  for (std::uint32_t j : nb) {
    if constexpr (SkipWalls) if (p.kind[j]) continue;
    const double dx = xi - p.x[0][j], dy = yi - p.x[1][j], dz = zi - p.x[2][j];
    const double r2 = dx * dx + dy * dy + dz * dz;
    c.r[n] = r2;
    c.w[n] = Volume ? m[i] : m[j];
    n += r2 < reach2 ? 1 : 0;  // keeps the entry only inside the reach (no branch)
  }
  c.n = n;
  double* r = c.r.data();
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) r[k] = std::sqrt(r[k]);  // once, not at every Newton iteration
}

/// Neighbours inside the support of h (the stage's neighbour count).
template <class Shape>
int count_within(const Candidates& c, double h) {
  const double R = Shape::support * h;
  int count = 0;
  for (std::size_t k = 0; k < c.n; ++k) count += c.r[k] < R ? 1 : 0;
  return count;
}

/// The sums at smoothing length h (seed 000 eqs. 3.2.17, 3.3.2): with q = r/h, W = sigma w(q)/h^d and
/// dW/dh = -sigma (d w(q) + q w'(q))/h^(d+1), so one evaluation of the shape gives both. The terms are
/// computed in a loop without reductions (vectorised), then summed in list order: the same sums, bit for
/// bit, as one running sum over the candidates.
template <class Shape>
Sums sums_at(const Shape& shape, double sigma, int d, Candidates& c, double h) {
  const double hinv = 1.0 / h;
  const double dd = d;
  const std::size_t n = c.n;
  const double* R = c.r.data();
  const double* CW = c.w.data();
  double* TW = c.tw.data();
  double* TD = c.td.data();
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) {
    const double q = R[k] * hinv;
    const double w = shape.w(q), dw = shape.dw(q);  // 0 beyond the support
    TW[k] = CW[k] * w;
    TD[k] = CW[k] * (dd * w + q * dw);
  }
  double sw = 0.0, sd = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    sw += TW[k];
    sd += TD[k];
  }
  double hd = hinv;
  for (int k = 1; k < d; ++k) hd *= hinv;
  return Sums{sigma * hd * sw, -sigma * hd * hinv * sd};
}

/// One evaluation's h solve: the fields and settings every particle's solve shares. Volume: rho_a =
/// m_a sum_b W_ab; SkipWalls: Lennard-Jones wall particles are not in the sums.
template <bool Volume, bool SkipWalls, class Shape>
struct HSolve {
  const StageContext& c;
  const Shape shape;
  const std::vector<double>& m;
  std::vector<double>&rho, &h, &omega, &nneigh, &hiter;
  const int d;
  const double eta_d;
  const bool fixed;
  const double tol;
  const int max_iter;
  const std::vector<double>& h_limit;
  /// the first guess of the solve: h + dh/dt times the time since the last one (the rate of the last
  /// force evaluation), inside [h/2, h_limit]
  const double* hdot;
  const double since, sigma, support;

  HSolve(StageContext& ctx, const Shape& s, bool fixed_h)
      : c(ctx), shape(s), m(ctx.p[Field::Mass]), rho(ctx.p[Field::Density]), h(ctx.p[Field::H]),
        omega(ctx.p[Field::Omega]), nneigh(ctx.p[Field::Neighbours]), hiter(ctx.p[Field::HIterations]),
        d(ctx.p.dim()), eta_d(std::pow(ctx.eta, d)), fixed(fixed_h), tol(ctx.prm.h.tol),
        max_iter(ctx.prm.h.max_iter), h_limit(ctx.h_limit),
        hdot(!fixed && ctx.since > 0.0 && ctx.p.has(Field::HRate) ? ctx.p[Field::HRate].data() : nullptr),
        since(ctx.since), sigma(ctx.kernel.sigma()), support(ctx.kernel.support()) {}

  /// Particle i's h, rho, Omega, neighbour count and iterations (+1000 if not converged); false if h
  /// reached its list's limit (h is left there). cand: this thread's scratch.
  bool particle(std::size_t i, Candidates& cand, std::size_t& bisections) const {
    const double reach = support * (fixed ? h[i] : h_limit[i]);
    gather<Volume, SkipWalls>(c.p, i, c.nl.of(i), m, reach * reach, cand);
    Sums s;
    double hi = h[i];
    if (hdot) hi = std::clamp(hi + hdot[i] * since, 0.5 * hi, h_limit[i]);
    int it = 0;
    bool converged = true;
    if (fixed) {
      s = sums_at(shape, sigma, d, cand, hi);
    } else {
      // g(h) = rho(h) - m eta^d / h^d  (seed 000 eq. 3.5.1); g' = drho/dh + d m eta^d / h^(d+1)
      const NewtonResult r = newton_bracketed(
          [&](double hh, double& g, double& dg) {
            s = sums_at(shape, sigma, d, cand, hh);
            double hd = hh;
            for (int k = 1; k < d; ++k) hd *= hh;
            const double target = m[i] * eta_d / hd;
            g = s.rho - target;
            dg = s.drho + d * target / hh;
          },
          hi, h_limit[i], tol, max_iter);
      if (r.hit_upper) { h[i] = h_limit[i]; return false; }
      bisections += static_cast<std::size_t>(r.bisections);
      it = r.iterations;
      converged = r.converged;
      hi = r.x;  // s holds the sums evaluated at r.x (the last evaluation)
    }
    h[i] = hi;
    rho[i] = s.rho;
    // Omega = 1 - (dh/drho) sum m dW/dh with dh/drho = -h/(rho d)  (seed 000 eqs. 3.3.2, 3.3.4)
    omega[i] = fixed ? 1.0 : 1.0 + hi / (d * s.rho) * s.drho;
    nneigh[i] = count_within<Shape>(cand, hi);
    hiter[i] = it + (converged ? 0.0 : 1000.0);  // > 1000 marks non-converged particles
    return true;
  }
};

/// The solve's statistics from the particles' iteration and neighbour counts; clears the 1000 marks.
void record_stats(StageContext& c, std::size_t bisections) {
  Particles& p = c.p;
  const std::size_t n = p.fluid();
  auto& nneigh = p[Field::Neighbours];
  auto& hiter = p[Field::HIterations];
  double sum_it = 0.0, sum_nb = 0.0;  // sums of integers: exact, so the same for any thread count
  std::size_t not_converged = 0, first_bad = n;
  int max_it = 0;
  DensityStats& stats = c.stats.density;
  stats = DensityStats{};
  stats.bisections = bisections;
#pragma omp parallel for reduction(+ : sum_it, sum_nb, not_converged) reduction(max : max_it) reduction(min : first_bad) if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    int it = static_cast<int>(hiter[i]);
    if (it >= 1000) { ++not_converged; it -= 1000; hiter[i] = it; first_bad = std::min(first_bad, i); }
    sum_it += it;
    max_it = std::max(max_it, it);
    sum_nb += nneigh[i];
  }
  stats.not_converged = not_converged;
  stats.first_not_converged = first_bad < n ? static_cast<std::int64_t>(p.id[first_bad]) : -1;
  stats.max_iterations = max_it;
  stats.mean_iterations = n ? sum_it / n : 0.0;
  stats.mean_neighbours = n ? sum_nb / n : 0.0;
}

class DensitySummation final : public Stage {
 public:
  bool reads_every_list() const override { return false; }  // the summed rows (active and their neighbours)
  DensitySummation(bool volume, bool fixed)
      : Stage({.name = volume ? "density: volume 1/V = sum W" : "density: summation",
               .needs = {Field::Mass, Field::H},
               .writes = {Field::Density, Field::H, Field::Omega, Field::Neighbours, Field::HIterations},
               .shares = {Field::Density, Field::H, Field::Omega}}),
        volume_(volume), fixed_(fixed) {}

  bool run(StageContext& c) override {
    const bool skip = c.prm.physics.walls == WallType::LennardJones;
    return shape::with_shape(c.kernel.type(), c.p.dim(), [&](auto s) {
      if (volume_) return skip ? solve<true, true>(c, s) : solve<true, false>(c, s);
      return skip ? solve<false, true>(c, s) : solve<false, false>(c, s);
    });
  }

 private:
  template <bool Volume, bool SkipWalls, class Shape>
  bool solve(StageContext& c, const Shape& shape) {
    const std::size_t n = c.p.fluid();
    const HSolve<Volume, SkipWalls, Shape> hs(c, shape, fixed_);
    int overflow = 0;
    std::size_t bisections = 0;
#pragma omp parallel reduction(+ : overflow, bisections) if (c.p.size() >= kParallelMin)
    {
    Candidates cand;  // this thread's
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
    for (std::size_t k = 0; k < c.summed_rows(n); ++k)  // individual time steps: active and their neighbours
      if (!hs.particle(c.summed_row(k), cand, bisections)) ++overflow;
    }
    if (overflow > 0) return false;
    // wall particles solve no h: Omega = 1 in the forces' P_b/(Omega_b rho_b^2) (unset, 0/0 stopped the
    // standard form beside dummy walls at its first step: dam_break with physics.force=standard)
    auto& omega = c.p[Field::Omega];
    std::fill(omega.begin() + static_cast<std::ptrdiff_t>(n), omega.begin() + static_cast<std::ptrdiff_t>(c.p.size()), 1.0);
    record_stats(c, bisections);
    return true;
  }

  bool volume_, fixed_;
};

}  // namespace

std::unique_ptr<Stage> make_density_summation(const Physics& ph, int) {
  return std::make_unique<DensitySummation>(ph.density == DensityMode::Volume, ph.smoothing == HMode::Fixed);
}

}  // namespace sph
