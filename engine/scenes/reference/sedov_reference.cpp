#include "reference/sedov_reference.h"

#include <cmath>

#include "reference/compared_columns.h"
#include "reference/radial_curves.h"
#include "reference/radial_profile.h"
#include "reference/sedov_solution.h"

namespace sph::scenes {
namespace {

class SedovReference final : public Reference {
 public:
  explicit SedovReference(const SedovSetup& s) : s_(s), sol_(s.dim, s.gamma) {}
  std::vector<RefColumn> columns() const override {
    std::vector<RefColumn> c = compared_columns(
        "R", "shock radius from the particles: where the shell-mean density falls half way from its peak to rho1 [length]",
        "self-similar radius xi0 (E t^2/rho1)^(1/(d+2)) [length]");
    append_columns(c, {{"rho_peak", "largest shell-mean density (exact: (gamma+1)/(gamma-1) rho1 at the shock) [mass/length^d]", false},
                       {"L1_rho", "mean |rho - rho_exact(r)| over the particles with r < 1.25 R_exact [mass/length^d]", true},
                       {"dE_rel", "|E(t)/E(0) - 1|, E = sum m (u + v^2/2), E(0) = E_blast + sum m u_ambient", true}});
    return c;
  }
  std::vector<double> evaluate(const Particles& p, double t) const override {
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    double M = 0.0, energy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      M += m[i];
      energy += m[i] * (p[Field::Energy][i] + 0.5 * p.vel(i).norm2());
    }
    const double E0 = s_.E + M * s_.u_ambient;
    const double dE = std::abs(energy / E0 - 1.0);
    if (!(t > 0.0)) return {0.0, 0.0, std::nan(""), 1.0, 0.0, dE};
    const double R_exact = sol_.shock_radius(s_.E, s_.rho1, t);
    const auto bins = static_cast<std::size_t>(s_.r_max / s_.dr);
    const RadialProfile prof = radial_profile(p, Field::Density, s_.dr, bins);
    const double R = shock_front(prof, s_.rho1);
    double l1 = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = p.pos(i).norm();
      if (r >= 1.25 * R_exact) continue;
      l1 += std::abs(p[Field::Density][i] - sol_.state(r, t, s_.E, s_.rho1).rho);
      ++count;
    }
    return {R, R_exact, relative_error(R, R_exact), profile_peak(prof, 3).value, count ? l1 / count : 0.0, dE};
  }
  std::string description() const override {
    return "Sedov-Taylor blast (d = " + std::to_string(s_.dim) + ", gamma = " + std::to_string(s_.gamma) +
           ", xi0 = " + std::to_string(sol_.xi0()) +
           "): shock radius from shells of width dr against xi0 (E t^2/rho1)^(1/(d+2)), density against the "
           "self-similar profile (Sedov 1959; Kamm & Timmes 2007), total energy drift";
  }
  int primary() const override { return 2; }
  std::vector<std::pair<int, int>> series() const override { return {{0, 1}}; }
  /// rho, |v| and P against r out to 1.5 R (axis 3: the distance from the origin).
  ReferenceCurves curves(const Domain&, double t) const override {
    if (!(t > 0.0)) return {};
    const double R = sol_.shock_radius(s_.E, s_.rho1, t);
    RadialCurves rc;
    auto add = [&](double r) {
      const SedovSolution::State q = sol_.state(r, t, s_.E, s_.rho1);
      rc.add(r, q.rho, q.v, r < R ? q.P : (s_.gamma - 1.0) * s_.rho1 * s_.u_ambient);
    };
    for (int k = 0; k < 400; ++k) add(R * k / 400.0);
    add(R * (1.0 - 1e-7));  // the jump: the post-shock state, then the ambient gas
    for (int k = 0; k <= 50; ++k) add(R * (1.0 + 0.5 * k / 50.0));
    return rc.take();
  }

 private:
  SedovSetup s_;
  SedovSolution sol_;
};

}  // namespace

std::unique_ptr<Reference> make_sedov_reference(const SedovSetup& s) { return std::make_unique<SedovReference>(s); }

}  // namespace sph::scenes
