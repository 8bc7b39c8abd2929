// Self-gravity (seed 003 eqs. 2.3, 2.43; App. A): a += -G sum_j m_j f(r_ij) (x_i - x_j) by direct
// summation, a Barnes-Hut tree or the fast multipole method, with Plummer or kernel softening; phi_i
// is stored for display and the potential energy E_pot = 1/2 sum m_i phi_i (seed 003 eq. 2.8). It
// needs no neighbour lists.
// Timestep limits: sqrt(eps / |a|) for Plummer softening (the world applies sqrt(h/|a|) to h > 0), and
// the shortest two-body dynamical time sqrt(r^3 / (G (m_i + m_j))) over the pairs summed one by one,
// which resolves close encounters and orbits of point masses (a fraction of it, by the Courant factor).
// With individual time steps only the active particles are evaluated (gravity/sources.h: Sources::active).
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

  // With individual time steps only the active particles are sinks: the others are drifted, keep the
  // accelerations of their last evaluation (the integrator restores them) and their potentials. The
  // potential energy of such a state is then carried from the last full evaluation by the work of the
  // accelerations the integrator uses, dE_pot = -sum m_i g_i . dx_i (trapezoidal in g over each
  // sub-step); summing the mixed potentials instead was off by up to 0.2 of the energy scale in evrard.
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const bool some = c.active && c.active->size() < n;
    if (some) {
      sinks_.assign(n, 0);
      for (std::uint32_t i : *c.active) sinks_[i] = 1;
    }
    const bool carry = some && e_pot_known_ && x_eval_[0].size() == n && out_.a[0].size() == n;
    const double work_before = carry ? work(p) : 0.0;
    solve(c, p, out_, some ? sinks_.data() : nullptr);
    if (carry) {
      e_pot_ -= 0.5 * (work_before + work(p));
    } else if (some) {
      e_pot_known_ = false;  // potential() solves again
    } else {
      const auto& m = p[Field::Mass];
      e_pot_ = 0.0;  // serial: the same for any thread count
      for (std::size_t i = 0; i < n; ++i) e_pot_ += 0.5 * m[i] * out_.phi[i];
      e_pot_known_ = true;
    }
    const std::size_t rows = c.rows(n);
    for (int k = 0; k < 3; ++k) {
      auto& a = p.a[k];
      const auto& g = out_.a[k];
#pragma omp parallel for schedule(static) if (rows >= kParallelMin)
      for (std::size_t r = 0; r < rows; ++r) a[c.row(r)] += g[c.row(r)];
    }
    std::copy(out_.phi.begin(), out_.phi.end(), p[Field::Potential].begin());
    // the state out_ belongs to; inside a block of individual steps the inactive particles' potentials
    // (the field phi) are those of their last evaluation; the block's end evaluates every particle
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

  // the last evaluation's accelerations, potentials and pair times (dt_limit reads them), positions, and
  // the potential energy with whether it is known
  std::vector<std::vector<double>> saved_state() const override {
    return {out_.a[0], out_.a[1], out_.a[2], out_.phi, out_.t2_pair, x_eval_[0], x_eval_[1], x_eval_[2],
            {e_pot_, e_pot_known_ ? 1.0 : 0.0}};
  }
  bool restore_state(const std::vector<std::vector<double>>& s) override {
    if (s.size() != 9 || s[8].size() != 2) return false;
    for (int k = 0; k < 3; ++k) {
      out_.a[k] = s[k];
      x_eval_[k] = s[5 + k];
    }
    out_.phi = s[3];
    out_.t2_pair = s[4];
    e_pot_ = s[8][0];
    e_pot_known_ = s[8][1] != 0.0;
    return true;
  }

  // the kept values follow the particles (the inactive ones' are read until they are active again)
  void permute(std::span<const std::uint32_t> order) override {
    std::vector<double> old;
    auto follow = [&](std::vector<double>& v) {
      for (std::size_t k = 0; k < v.size(); ++k)
        if (k >= order.size() || order[k] >= v.size()) {  // another set of particles: nothing to keep
          v.clear();
          return;
        }
      old = v;
      for (std::size_t k = 0; k < v.size(); ++k) v[k] = old[order[k]];
    };
    for (int k = 0; k < 3; ++k) {
      follow(out_.a[k]);
      follow(x_eval_[k]);
    }
    follow(out_.phi);
    follow(out_.t2_pair);
  }

  double potential(const StageContext& c) const override {
    const Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    if (evaluated_at(p) && e_pot_known_) return e_pot_;
    solve(c, p, scratch_);  // the last evaluation was at another state (an RK4 sub-step)
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < n; ++i) e += 0.5 * m[i] * scratch_.phi[i];
    return e;
  }

 private:
  /// sum_i m_i g_i . (x_i - x_i at the last evaluation), g the accelerations out_ holds (serial).
  double work(const Particles& p) const {
    const auto& m = p[Field::Mass];
    double w = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i)
      for (int k = 0; k < p.dim(); ++k) w += m[i] * out_.a[k][i] * (p.x[k][i] - x_eval_[k][i]);
    return w;
  }
  /// Accelerations and potentials for the current positions: of every particle, or of the sinks flagged
  /// in `sinks` (out keeping the others').
  void solve(const StageContext& c, const Particles& p, gravity::Result& out, const std::uint8_t* sinks = nullptr) const {
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
    gravity::Sources s = gravity::Sources::of(p);
    s.active = sinks;
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
  std::vector<std::uint8_t> sinks_;            ///< the active particles' flags (individual time steps)
  double e_pot_ = 0.0;                         ///< the potential energy at x_eval_ (run())
  bool e_pot_known_ = false;
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
