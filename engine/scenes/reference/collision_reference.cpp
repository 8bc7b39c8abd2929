#include "reference/collision_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reference/lane_emden.h"
#include "reference/two_body_orbit.h"

namespace sph::scenes {
namespace {

class CollisionReference final : public Reference {
 public:
  CollisionReference(const Params& prm, std::size_t n, double M, Vec3 r0, Vec3 v0)
      : n_(n), sc_(Polytrope(1.0 / (prm.gas.gamma - 1.0), M, prm.gas.K, prm.gravity.G).scales),
        // the point masses are followed down to R/10 (a head-on fall reaches r = 0 in finite time)
        orbit_(r0, v0, prm.gravity.G * 2.0 * M, std::max(2.0 * prm.time.t_end, 20.0), 0.1 * sc_.R),
        t_contact_(orbit_.time_to(2.0 * sc_.R)) {}

  std::vector<RefColumn> columns() const override {
    return {{"separation", "distance between the centres of mass of the two stars [length]", false},
            {"separation_2body", "the same for two point masses from the same start (nan below R/10) [length]", false},
            {"sep_err", "|separation - separation_2body| / R until the point masses are 2 R apart (contact)", true},
            {"rho_max", "largest SPH density [mass/length^3]", false},
            {"rho_max_rel", "rho_max / rho_c, rho_c the central density of the Lane-Emden star", false},
            {"com", "distance of the total centre of mass from the origin, where it starts [length]", true}};
  }

  std::vector<double> evaluate(const Particles& p, double t) const override {
    const auto& m = p[Field::Mass];
    Vec3 c[2];
    double M[2] = {0.0, 0.0}, rho_max = 0.0;
    for (std::size_t i = 0; i < p.fluid(); ++i) {  // serial: the same for any thread count
      const int s = static_cast<std::size_t>(p.id[i]) < n_ ? 0 : 1;
      c[s] += p.pos(i) * m[i];
      M[s] += m[i];
      if (p.has(Field::Density)) rho_max = std::max(rho_max, p[Field::Density][i]);
    }
    const Vec3 com = (c[0] + c[1]) * (1.0 / (M[0] + M[1]));
    const double sep = (c[1] * (1.0 / M[1]) - c[0] * (1.0 / M[0])).norm();
    const double two = orbit_.separation(t);
    const double err = !(t >= t_contact_) ? std::abs(sep - two) / sc_.R : std::nan("");  // no contact: always
    return {sep, two, err, rho_max, rho_max / sc_.rho_c, com.norm()};
  }

  std::string description() const override {
    char text[320];
    std::snprintf(text, sizeof text,
                  "colliding polytropes (seed 003 §3.4.4): separation of the stars' centres of mass against two point "
                  "masses (contact, 2 R apart, at t = %.4g; R apart at t = %.4g), peak density against rho_c = %.4g",
                  t_contact_, orbit_.time_to(sc_.R), sc_.rho_c);
    return text;
  }
  int primary() const override { return 2; }
  std::vector<std::pair<int, int>> series() const override { return {{0, 1}}; }

 private:
  std::size_t n_;
  PolytropeScales sc_;
  TwoBodyOrbit orbit_;
  double t_contact_;  ///< the point masses first 2 R apart (nan: never)
};

}  // namespace

std::unique_ptr<Reference> make_collision_reference(const Params& prm, std::size_t n, double M, Vec3 r0, Vec3 v0) {
  return std::make_unique<CollisionReference>(prm, n, M, r0, v0);
}

}  // namespace sph::scenes
