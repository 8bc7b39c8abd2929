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
// Timestep (before the Courant factor): the seed's CFL condition dt <= dx / (2 max|u|) (§4) and, for the
// viscous scheme, the explicit diffusion limit dt <= dx^2 / (2 eps), which the seed does not state but
// which binds from about 400 points at eps = 0.005 (forward Euler on u_xx is unstable beyond it).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/parallel.h"
#include "core/stages.h"
#include "fpm/mls.h"
#include "sph/config.h"

namespace sph {
namespace {

class FpmBurgers final : public Stage {
 public:
  explicit FpmBurgers(FpmType type) : type_(type) {}
  std::string_view name() const override {
    return type_ == FpmType::BurgersUpwind ? "FPM Burgers: upwind (seed 002 eqs. 18-21)"
                                           : "FPM Burgers: viscous (seed 002 eqs. 16-17)";
  }
  FieldSet needs() const override { return FieldSet{}.add(Field::Mass).add(Field::H).add(Field::RestX); }
  FieldSet writes() const override {
    return type_ == FpmType::BurgersUpwind ? FieldSet{}.add_vector(Field::XsphX) : FieldSet{};
  }
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

  bool acts_after(const Params& prm, std::int64_t) const override {
    return prm.fpm.control == PointControl::Reinterpolate;
  }
  /// Note 3.2: u at the initial points Gamma_0 by MLS from the moved points; the points go back there.
  void after_step(StageContext& c) override {
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
    double dt = umax > 0.0 ? 0.5 * c.spacing / umax : kNoLimit;  // seed 002 §4
    if (type_ == FpmType::BurgersViscous && c.prm.fpm.eps > 0.0)
      dt = std::min(dt, c.spacing * c.spacing / (2.0 * c.prm.fpm.eps));
    return dt;
  }

 private:
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
};

}  // namespace

std::unique_ptr<Stage> make_fpm_burgers(FpmType type, int dim) {
  if (dim != 1) throw ConfigError("physics.fpm: the finite pointset method is implemented in 1D only");
  return std::make_unique<FpmBurgers>(type);
}

}  // namespace sph
