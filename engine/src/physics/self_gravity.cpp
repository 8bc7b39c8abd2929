// Self-gravity (seed 003 eqs. 2.3, 2.43; App. A): a += -G sum_j m_j f(r_ij) (x_i - x_j) by direct
// summation, a Barnes-Hut tree or the fast multipole method, with Plummer or kernel softening; phi_i
// is stored for display and the potential energy E_pot = 1/2 sum m_i phi_i (seed 003 eq. 2.8). It
// needs no neighbour lists.
// Timestep limits: sqrt(eps / |a|) for Plummer softening (the world applies sqrt(h/|a|) to h > 0), and
// the shortest two-body dynamical time sqrt(r^3 / (G (m_i + m_j))) over the pairs summed one by one,
// which resolves close encounters and orbits of point masses (a fraction of it, by the Courant factor).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <span>

#include "core/parallel.h"
#include "core/stages.h"
#include "gravity/barnes_hut.h"
#include "gravity/direct_sum.h"
#include "gravity/fmm.h"

namespace sph {
namespace {

class SelfGravity final : public Stage {
 public:
  explicit SelfGravity(GravityType type)
      : Stage({.name = type == GravityType::Tree  ? "self-gravity: Barnes-Hut tree"
                       : type == GravityType::Fmm ? "self-gravity: fast multipole method"
                                                  : "self-gravity: direct summation",
               .needs = {Field::Mass, Field::H},
               .writes = {Field::Potential}}),
        type_(type) {}
  bool uses_neighbours() const override { return false; }

  bool run(StageContext& c) override {
    Particles& p = c.p;
    solve(c, p, out_);
    const std::size_t n = p.fluid();
    for (int k = 0; k < 3; ++k) {
      auto& a = p.a[k];
      const auto& g = out_.a[k];
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
      for (std::size_t i = 0; i < n; ++i) a[i] += g[i];
    }
    std::copy(out_.phi.begin(), out_.phi.end(), p[Field::Potential].begin());
    for (int k = 0; k < 3; ++k) x_eval_[k].assign(p.x[k].begin(), p.x[k].begin() + static_cast<std::ptrdiff_t>(n));
    return true;
  }

  double dt_limit(const StageContext& c) const override {
    const Particles& p = c.p;
    const std::size_t n = std::min(p.fluid(), out_.t2_pair.size());
    const bool plummer = c.prm.gravity.softening == Softening::Plummer && c.prm.gravity.eps > 0.0;
    const double eps = c.prm.gravity.eps;
    double t2 = kNoLimit;  // a minimum: the same for any thread count
#pragma omp parallel for reduction(min : t2) if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      t2 = std::min(t2, out_.t2_pair[i]);
      if (!plummer) continue;
      const double a2 = p.a[0][i] * p.a[0][i] + p.a[1][i] * p.a[1][i] + p.a[2][i] * p.a[2][i];
      if (a2 > 0.0) t2 = std::min(t2, eps / std::sqrt(a2));
    }
    return t2 < 1e299 ? std::sqrt(t2) : kNoLimit;
  }

  // the same limits per particle (individual time steps)
  void dt_limits(const StageContext& c, std::span<double> dt) const override {
    const Particles& p = c.p;
    const std::size_t n = std::min({p.fluid(), out_.t2_pair.size(), dt.size()});
    const bool plummer = c.prm.gravity.softening == Softening::Plummer && c.prm.gravity.eps > 0.0;
    const double eps = c.prm.gravity.eps;
#pragma omp parallel for if (n >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      double t2 = out_.t2_pair[i];
      const double a2 = p.a[0][i] * p.a[0][i] + p.a[1][i] * p.a[1][i] + p.a[2][i] * p.a[2][i];
      if (plummer && a2 > 0.0) t2 = std::min(t2, eps / std::sqrt(a2));
      if (t2 < 1e299) dt[i] = std::min(dt[i], std::sqrt(t2));
    }
  }

  // the last evaluation's accelerations, potentials and pair times (dt_limit reads them) and positions
  std::vector<std::vector<double>> saved_state() const override {
    return {out_.a[0], out_.a[1], out_.a[2], out_.phi, out_.t2_pair, x_eval_[0], x_eval_[1], x_eval_[2]};
  }
  bool restore_state(const std::vector<std::vector<double>>& s) override {
    if (s.size() != 8) return false;
    for (int k = 0; k < 3; ++k) {
      out_.a[k] = s[k];
      x_eval_[k] = s[5 + k];
    }
    out_.phi = s[3];
    out_.t2_pair = s[4];
    return true;
  }

  double potential(const StageContext& c) const override {
    const Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    const std::vector<double>* phi = &out_.phi;
    if (!evaluated_at(p)) {  // the last evaluation was at another state (an RK4 sub-step)
      solve(c, p, scratch_);
      phi = &scratch_.phi;
    }
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < n; ++i) e += 0.5 * m[i] * (*phi)[i];
    return e;
  }

 private:
  /// Accelerations and potentials for the current positions.
  void solve(const StageContext& c, const Particles& p, gravity::Result& out) const {
    const GravityParams& g = c.prm.gravity;
    gravity::PairLaw law;
    law.kind = g.softening;
    law.eps2 = g.eps * g.eps;
    if (kernel_softened(g.softening)) {
      if (!kernel_ || kernel_type_ != c.prm.kernel.type) {
        kernel_.emplace(c.prm.kernel.type);
        kernel_type_ = c.prm.kernel.type;
      }
      law.kernel = &*kernel_;
    }
    const gravity::Sources s = gravity::Sources::of(p);
    if (type_ == GravityType::Direct) {
      gravity::direct_sum(s, law, g.G, out);
    } else if (type_ == GravityType::Fmm) {
      if (!fmm_ || fmm_->order() != g.fmm_order) fmm_ = std::make_unique<gravity::FastMultipole>(g.fmm_order);
      fmm_->build(s);
      fmm_->evaluate(s, law, g.G, g.fmm_theta, out, g.fmm_tol);
    } else {
      tree_.build(s);
      tree_.evaluate(s, law, g.G, g.theta, out, g.tol);
    }
  }
  bool evaluated_at(const Particles& p) const {
    const std::size_t n = p.fluid();
    for (int k = 0; k < 3; ++k)
      if (x_eval_[k].size() != n || !std::equal(x_eval_[k].begin(), x_eval_[k].end(), p.x[k].begin())) return false;
    return true;
  }

  GravityType type_;
  gravity::Result out_;
  std::array<std::vector<double>, 3> x_eval_;  ///< positions of the last evaluation
  // caches of const methods (diagnostics run on the thread that steps)
  mutable gravity::Result scratch_;
  mutable gravity::BarnesHutTree tree_;
  mutable std::unique_ptr<gravity::FastMultipole> fmm_;
  mutable std::optional<gravity::KernelSoftening> kernel_;
  mutable KernelType kernel_type_ = KernelType::M4;
};

}  // namespace

std::unique_ptr<Stage> make_self_gravity(GravityType type) { return std::make_unique<SelfGravity>(type); }

}  // namespace sph
