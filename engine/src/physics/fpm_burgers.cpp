// The finite pointset method on Burgers' equation (seed 002): the particles are the points, their
// velocity v_x is u, and the derivatives come from moving least squares (fpm/mls.h) over the engine's
// neighbour lists (the seed's head/next cell list of Programs 2-3 is neighbours/cell_list.cpp).
//  - viscous (eqs. 6a-6b): Du/Dt = eps u_xx, Dx/Dt = u; with the Euler integrator this is eqs. 16-17.
//  - upwind (eqs. 18-19): Du/Dt = -(1/2) u u_x with the one-sided derivative from the side the
//    characteristics come from, Dx/Dt = u/2 (the drift field holds -u/2); with Euler, eqs. 20-21.
//    Seed misprint: eq. 21 reads "- min(u,0) Pi+ u_x"; u u_x needs "+ min(u,0) Pi+ u_x" (for u < 0 the
//    printed sign gives Du/Dt = +u u_x / 2). The seed's runs have u >= 0, where both agree.
// Point control (Note 3.2), fpm.control = reinterpolate: after every step u is interpolated by MLS
// from the moved points back onto their initial places Gamma_0 (field x0), and the points return there.
// merge_split (the Note's alternative): the points move with the flow; two points closer than dx0/2
// are replaced by their midpoint, a gap wider than 3 dx0/2 gets a midpoint, u linearly interpolated
// (the seed gives no thresholds: these are ours). Not in the seed either, and needed for a closed
// point set: a point enters at the inflow end when the first one has moved dx0 away from it (u of its
// neighbour), and points beyond the outflow end leave.
// Timestep (before the Courant factor): the seed's CFL condition dt <= dx / (2 max|u|) (§4) and, for the
// viscous scheme, the explicit diffusion limit dt <= dx^2 / (2 eps), which the seed does not state but
// which binds where dx < eps (from about 500 points on [-0.5, 2] at eps = 0.005; forward Euler on u_xx
// is unstable beyond it).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "core/parallel.h"
#include "core/stages.h"
#include "fpm/mls.h"
#include "sph/config.h"

namespace sph {
namespace {

/// Reads the points' masses, h and initial places; the upwind scheme writes the drift (-u/2).
StageContract contract(FpmType type) {
  const bool upwind = type == FpmType::BurgersUpwind;
  StageContract c{.name = upwind ? "FPM Burgers: upwind (seed 002 eqs. 18-21)"
                                 : "FPM Burgers: viscous (seed 002 eqs. 16-17)",
                  .needs = {Field::Mass, Field::H, Field::RestX}};
  if (upwind) c.writes.add_vector(Field::XsphX);
  return c;
}

class FpmBurgers final : public Stage {
 public:
  explicit FpmBurgers(FpmType type) : Stage(contract(type)), type_(type) {}
  bool sets_acceleration() const override { return true; }

  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& h = p[Field::H];
    const double eps = c.prm.fpm.eps;
    const bool upwind = type_ == FpmType::BurgersUpwind;
#pragma omp parallel if (n >= kParallelMin)
    {
      std::vector<double> xs, us;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        gather(c, i, xs, us);
        fpm::MlsOptions opt{h[i], c.prm.fpm.alpha, fpm::Side::Both};
        const double u = p.v[0][i];
        double a = 0.0;
        if (!upwind) {
          a = eps * fpm::mls_fit(p.x[0][i], xs, us, opt).d2f;  // eq. 16
        } else if (u != 0.0) {
          opt.side = u > 0.0 ? fpm::Side::Left : fpm::Side::Right;  // upstream neighbours only
          a = -0.5 * u * fpm::mls_fit(p.x[0][i], xs, us, opt).df;  // eq. 21, sign corrected
        }
        p.a[0][i] = a;
        p.a[1][i] = p.a[2][i] = 0.0;
      }
    }
    if (upwind) {
      auto& drift = p[Field::XsphX];
      for (std::size_t i = 0; i < n; ++i) drift[i] = -0.5 * p.v[0][i];  // Dx/Dt = u/2 (eq. 19)
      std::fill_n(p[Field::XsphY].begin(), n, 0.0);
      std::fill_n(p[Field::XsphZ].begin(), n, 0.0);
    }
    return true;
  }

  bool acts_after(const Params& prm, std::int64_t) const override { return prm.fpm.control != PointControl::None; }
  /// Note 3.2: u at the initial points Gamma_0 by MLS from the moved points; the points go back there.
  void after_step(StageContext& c) override {
    if (c.prm.fpm.control == PointControl::MergeSplit) {
      merge_split(c);
      return;
    }
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& h = p[Field::H];
    auto& x0 = p[Field::RestX];
    fresh_.resize(n);
#pragma omp parallel if (n >= kParallelMin)
    {
      std::vector<double> xs, us;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        gather(c, i, xs, us);
        const fpm::MlsFit fit = fpm::mls_fit(x0[i], xs, us, {h[i], c.prm.fpm.alpha, fpm::Side::Both});
        fresh_[i] = fit.order >= 0 ? fit.f : p.v[0][i];
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      p.x[0][i] = x0[i];
      p.v[0][i] = fresh_[i];
    }
  }

  double dt_limit(const StageContext& c) const override {
    const Particles& p = c.p;
    double umax = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) umax = std::max(umax, std::abs(p.v[0][i]));
    // points that move (merge_split, none) are closer than dx0 in places: the limits use the
    // smallest distance between neighbours then
    double dx = c.spacing;
    if (c.prm.fpm.control != PointControl::Reinterpolate)
      for (std::size_t i = 0; i < p.fluid(); ++i)
        for (std::uint32_t j : c.nl.of(i))
          if (j != i) dx = std::min(dx, std::abs(p.x[0][i] - p.x[0][j]));
    double dt = umax > 0.0 ? 0.5 * dx / umax : kNoLimit;  // seed 002 §4
    if (type_ == FpmType::BurgersViscous && c.prm.fpm.eps > 0.0) dt = std::min(dt, dx * dx / (2.0 * c.prm.fpm.eps));
    return dt;
  }

  bool exact_lists() const override { return true; }  // the MLS fits take every listed point

  bool take_resampled(Particles& out) override {
    if (!resampled_) return false;
    out = std::move(*resampled_);
    resampled_.reset();
    return true;
  }

 private:
  struct Point {
    double x, u;
    std::size_t src;  ///< the particle whose other fields it takes
    std::int64_t id;  ///< -1: a new point
  };
  /// Note 3.2's alternative; builds resampled_ when the point set changed.
  void merge_split(const StageContext& c) {
    const Particles& p = c.p;
    const std::size_t n = p.fluid();
    if (n == 0) return;
    if (next_id_ < 0)
      for (std::size_t i = 0; i < p.size(); ++i) next_id_ = std::max(next_id_, p.id[i] + 1);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return p.x[0][a] < p.x[0][b] || (p.x[0][a] == p.x[0][b] && p.id[a] < p.id[b]);
    });
    const double dx = c.spacing, lo = c.domain.lo[0], hi = c.domain.hi[0];
    std::vector<Point> out;
    out.reserve(n + 8);
    bool changed = false;
    const std::size_t first = order.front();
    for (double x = p.x[0][first] - dx; x >= lo - 1e-12 * dx; x -= dx) {  // inflow: refill from the left end
      out.insert(out.begin(), Point{x, p.v[0][first], first, -1});
      changed = true;
    }
    for (std::size_t i : order) {
      const Point q{p.x[0][i], p.v[0][i], i, p.id[i]};
      if (q.x > hi) { changed = true; continue; }  // outflow
      if (!out.empty()) {
        Point& last = out.back();
        const double gap = q.x - last.x;
        if (gap < 0.5 * dx) {  // merge into the midpoint
          last = Point{0.5 * (last.x + q.x), 0.5 * (last.u + q.u), last.src, last.id};
          changed = true;
          continue;
        }
        if (gap > 1.5 * dx) {  // split the gap
          out.push_back(Point{0.5 * (last.x + q.x), 0.5 * (last.u + q.u), last.src, -1});
          changed = true;
        }
      }
      out.push_back(q);
    }
    if (!changed) {
      resampled_.reset();
      return;
    }
    Particles fresh(1, out.size(), p.fields());
    const FieldSet fields = p.fields();
    for (std::size_t k = 0; k < out.size(); ++k) {
      const Point& q = out[k];
      fields.for_each([&](Field f) { fresh[f][k] = p[f][q.src]; });
      fresh.x[0][k] = q.x;
      fresh.v[0][k] = q.u;
      fresh[Field::RestX][k] = q.x;
      fresh.id[k] = q.id >= 0 ? q.id : next_id_++;
    }
    resampled_ = std::move(fresh);
  }

  // the next id a new point gets (ids are below 2^53: exact as a double)
  std::vector<std::vector<double>> saved_state() const override { return {{static_cast<double>(next_id_)}}; }
  bool restore_state(const std::vector<std::vector<double>>& s) override {
    if (s.size() != 1 || s[0].size() != 1) return false;
    next_id_ = static_cast<std::int64_t>(s[0][0]);
    return true;
  }

  /// Positions and u of particle i's neighbours (itself included), in the list's fixed order.
  static void gather(const StageContext& c, std::size_t i, std::vector<double>& xs, std::vector<double>& us) {
    const auto nb = c.nl.of(i);
    xs.resize(nb.size());
    us.resize(nb.size());
    for (std::size_t k = 0; k < nb.size(); ++k) {
      xs[k] = c.p.x[0][nb[k]];
      us[k] = c.p.v[0][nb[k]];
    }
  }

  FpmType type_;
  std::vector<double> fresh_;
  std::optional<Particles> resampled_;
  std::int64_t next_id_ = -1;
};

}  // namespace

std::unique_ptr<Stage> make_fpm_burgers(FpmType type, int dim) {
  if (dim != 1) throw ConfigError("physics.fpm: the finite pointset method is implemented in 1D only");
  return std::make_unique<FpmBurgers>(type);
}

}  // namespace sph
