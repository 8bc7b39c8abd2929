#include "reference/noh_reference.h"

#include <cmath>

#include "reference/compared_columns.h"
#include "reference/radial_curves.h"
#include "reference/radial_profile.h"

namespace sph::scenes {
namespace {

class NohReference final : public Reference {
 public:
  explicit NohReference(const NohSetup& s) : s_(s) {}
  std::vector<RefColumn> columns() const override {
    std::vector<RefColumn> c = {
        {"rho_post", "mean density over R/3 < r < R - margin, R = U t (exact rho2: 16 for gamma 5/3 in 2D) [mass/length^d]", false},
        {"rho_post_err", "|rho_post / rho2 - 1|", true}};
    append_columns(c, compared_columns("R", "shock radius from the particles: where the shell-mean density falls half way "
                                            "from its peak to the exact pre-shock density [length]",
                                       "U t, U = (gamma-1) v0/2 (t/3) [length]"));
    append_columns(c, {{"rho_centre", "mean density over r < R/3, the wall-heating region [mass/length^d]", false},
                       {"rho_centre_deficit", "1 - rho_centre / rho2 (wall heating: the centre is hot and underdense)", true},
                       {"u_centre_excess", "mean u over r < R/3, over the exact u2 = v0^2/2, minus 1", true},
                       {"L1_rho", "mean |rho - rho_exact(r)| over the particles with r < 1.5 R [mass/length^d]", true}});
    return c;
  }
  std::vector<double> evaluate(const Particles& p, double t) const override {
    const Noh& noh = s_.noh;
    const double R_exact = noh.shock_radius(t), rho2 = noh.post_shock_density();
    const double nan = std::nan("");
    double post = 0.0, centre = 0.0, u_centre = 0.0, l1 = 0.0;
    std::size_t n_post = 0, n_centre = 0, n_l1 = 0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      const double r = p.pos(i).norm(), rho = p[Field::Density][i];
      if (r > R_exact / 3.0 && r < R_exact - s_.margin) {
        post += rho;
        ++n_post;
      }
      if (r < R_exact / 3.0) {
        centre += rho;
        u_centre += p[Field::Energy][i];
        ++n_centre;
      }
      if (r < 1.5 * R_exact && r > 0.0) {
        l1 += std::abs(rho - noh.state(r, t).rho);
        ++n_l1;
      }
    }
    const double rho_post = n_post ? post / n_post : nan, rho_c = n_centre ? centre / n_centre : nan;
    const double u_c = n_centre ? u_centre / n_centre : nan;
    double R = nan;
    if (t > 0.0) {
      const RadialProfile prof = radial_profile(p, Field::Density, s_.dr, static_cast<std::size_t>(s_.r_max / s_.dr));
      R = shock_front(prof, noh.state(R_exact * 1.0000001, t).rho);
    }
    const double u2 = 0.5 * noh.v0 * noh.v0;
    return {rho_post, relative_error(rho_post, rho2), R, R_exact, relative_error(R, R_exact),
            rho_c, 1.0 - rho_c / rho2, u_c / u2 - 1.0, n_l1 ? l1 / n_l1 : nan};
  }
  std::string description() const override {
    return "Noh implosion (Noh 1987; d = " + std::to_string(s_.noh.dim) + ", gamma = " + std::to_string(s_.noh.gamma) +
           "): post-shock density between the wall-heating region r < R/3 and R - " + std::to_string(s_.margin) +
           " against rho0 ((gamma+1)/(gamma-1))^d, the shock radius from shells against (gamma-1) v0 t/2, and the "
           "wall heating (density deficit and excess u at r < R/3)";
  }
  int primary() const override { return 1; }
  std::vector<std::pair<int, int>> series() const override { return {{2, 3}}; }
  /// rho, |v| and P against r (axis 3) out to the gas's edge r_max - v0 t.
  ReferenceCurves curves(const Domain&, double t) const override {
    const Noh& noh = s_.noh;
    const double R = noh.shock_radius(t), edge = s_.r_max - noh.v0 * t;
    if (!(t > 0.0) || !(edge > R)) return {};
    RadialCurves rc;
    auto add = [&](double r) {
      const NohState q = noh.state(r, t);
      rc.add(r, q.rho, std::abs(q.v), q.P);
    };
    add(0.0);
    add(R * (1.0 - 1e-7));
    for (int k = 0; k <= 200; ++k) add(R + (edge - R) * k / 200.0);
    return rc.take();
  }

 private:
  NohSetup s_;
};

}  // namespace

std::unique_ptr<Reference> make_noh_reference(const NohSetup& s) { return std::make_unique<NohReference>(s); }

}  // namespace sph::scenes
