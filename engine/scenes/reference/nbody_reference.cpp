#include "reference/nbody_reference.h"

#include <cmath>
#include <numbers>

#include "reference/compared_columns.h"

namespace sph::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

double lz(const Vec3& x, const Vec3& v, double m) { return m * (x.x * v.y - x.y * v.x); }

/// Position of the particle with id k (the storage order changes as particles are sorted).
Vec3 pos_of(const Particles& p, std::int64_t k) {
  for (std::size_t i = 0; i < p.fluid(); ++i)
    if (p.id[i] == k) return p.pos(i);
  return {std::nan(""), 0.0, 0.0};
}

class Conservation final : public Reference {
 public:
  Conservation(const std::vector<Body>& b, double G, double eps) : G_(G), eps_(eps), I0_(invariants(b, G, eps)) {}
  std::vector<RefColumn> columns() const override {
    return {{"E", "total energy sum m v^2/2 - sum G m m / r [mass length^2/time^2]", false},
            {"Lz", "angular momentum about the origin, z [mass length^2/time]", false},
            {"dE", "|E/E0 - 1| (seed 003 eq. 2.24)", true},
            {"dL", "|Lz/Lz0 - 1|", true}};
  }
  std::vector<double> evaluate(const Particles& p, double) const override {
    const Invariants I = invariants(p, G_, eps_);
    return {I.E, I.Lz, relative_error(I.E, I0_.E), relative_error(I.Lz, I0_.Lz)};
  }
  std::string description() const override {
    return "point masses: total energy and angular momentum against their initial values (seed 003 eqs. 2.8, 2.13, 2.24)";
  }
  int primary() const override { return 2; }

 private:
  double G_, eps_;
  Invariants I0_;
};

class Fall final : public Reference {
 public:
  Fall(const std::vector<Body>& b, double G)
      : r0_((b[1].x - b[0].x).norm()), mu_(G * (b[0].m + b[1].m)) {}
  std::vector<RefColumn> columns() const override {
    return {{"r", "separation of the two bodies [length]", false},
            {"r_exact", "separation from seed 003 eq. 2.17 [length]", false},
            {"err_r", "|r - r_exact| / r0 while r_exact > r0/20 (nan after: the encounter)", true}};
  }
  std::vector<double> evaluate(const Particles& p, double t) const override {
    const double r = (pos_of(p, 1) - pos_of(p, 0)).norm();
    const double re = t < fall_time(r0_, mu_) ? fall_separation(r0_, mu_, t) : 0.0;
    const double err = re > 0.05 * r0_ ? std::abs(r - re) / r0_ : std::nan("");
    return {r, re, err};
  }
  std::string description() const override {
    return "two bodies released at rest: separation against the closed-form fall of seed 003 eq. 2.17 (sign "
           "corrected, mu = G (m1 + m2))";
  }
  int primary() const override { return 2; }
  std::vector<std::pair<int, int>> series() const override { return {{0, 1}}; }

 private:
  double r0_, mu_;
};

class Kepler final : public Reference {
 public:
  Kepler(const std::vector<Body>& b, double G)
      : mu_(G * (b[0].m + b[1].m)), I0_(invariants(b, G, 0.0)), G_(G), star0_(b[0].x) {
    const Vec3 r = b[1].x - b[0].x, v = b[1].v - b[0].v;
    const double rn = r.norm();
    a_ = 1.0 / (2.0 / rn - v.norm2() / mu_);
    const Vec3 h = r.cross(v);
    sign_ = h.z >= 0.0 ? 1.0 : -1.0;
    const Vec3 ev = v.cross(h) * (1.0 / mu_) - r * (1.0 / rn);
    e_ = ev.norm();
    omega_ = e_ > 1e-12 ? std::atan2(ev.y, ev.x) : 0.0;
    const double nu0 = std::atan2(r.y, r.x) * sign_ - omega_ * sign_;
    const double E0 = 2.0 * std::atan(std::sqrt((1.0 - e_) / (1.0 + e_)) * std::tan(0.5 * nu0));
    M0_ = E0 - e_ * std::sin(E0);
    n_ = std::sqrt(mu_ / (a_ * a_ * a_));
  }
  std::vector<RefColumn> columns() const override {
    return {{"orbits", "t / T, the Kepler period T = 2 pi sqrt(a^3 / mu)", false},
            {"sep", "separation of the two bodies [length]", false},
            {"sep_exact", "separation on the Kepler orbit [length]", false},
            {"err_pos", "|r_rel - r_Kepler| / a: the relative position against the Kepler orbit", true},
            {"dE", "|E/E0 - 1|", true},
            {"dL", "|Lz/Lz0 - 1|", true}};
  }
  std::vector<double> evaluate(const Particles& p, double t) const override {
    const Vec3 r = pos_of(p, 1) - pos_of(p, 0);
    const Vec3 k = position(t);
    const Invariants I = invariants(p, G_, 0.0);
    return {t * n_ / (2.0 * kPi), r.norm(), k.norm(), (r - k).norm() / a_, relative_error(I.E, I0_.E),
            relative_error(I.Lz, I0_.Lz)};
  }
  std::string description() const override {
    return "two-body orbit: relative position against the Kepler orbit of the initial state (Kepler's equation), "
           "energy and angular momentum (seed 003 §2.4)";
  }
  int primary() const override { return 3; }
  std::vector<std::pair<int, int>> series() const override { return {{1, 2}}; }
  /// The exact orbit (an ellipse, 720 segments) about the first body's starting place: where the second
  /// body's trail should lie while the first barely moves (m_earth << 1).
  ReferenceCurves curves(const Domain&, double) const override {
    ReferenceCurves c;
    if (!(e_ < 1.0)) return c;
    Outline o;
    o.label = "Kepler orbit";
    const double c0 = std::cos(omega_), s0 = std::sin(omega_), b = a_ * std::sqrt(1.0 - e_ * e_);
    for (int k = 0; k <= 720; ++k) {
      const double E = 2.0 * kPi * k / 720.0, px = a_ * (std::cos(E) - e_), py = b * std::sin(E);
      o.x.push_back(static_cast<float>(star0_.x + c0 * px - s0 * py));
      o.y.push_back(static_cast<float>(star0_.y + s0 * px + c0 * py));
    }
    c.outlines.push_back(std::move(o));
    return c;
  }

  /// Relative position on the orbit at time t: E - e sin E = M0 + n t by Newton's method.
  Vec3 position(double t) const {
    const double M = M0_ + n_ * t;
    double E = M;
    for (int it = 0; it < 50; ++it) {
      const double dE = (E - e_ * std::sin(E) - M) / (1.0 - e_ * std::cos(E));
      E -= dE;
      if (std::abs(dE) < 1e-15) break;
    }
    const double px = a_ * (std::cos(E) - e_), py = a_ * std::sqrt(1.0 - e_ * e_) * std::sin(E) * sign_;
    const double c = std::cos(omega_), s = std::sin(omega_);
    return {c * px - s * py, s * px + c * py, 0.0};
  }

 private:
  double mu_;
  Invariants I0_;
  double G_;
  Vec3 star0_;
  double a_ = 1.0, e_ = 0.0, omega_ = 0.0, M0_ = 0.0, n_ = 1.0, sign_ = 1.0;
};

}  // namespace

Invariants invariants(const std::vector<Body>& b, double G, double eps) {
  Invariants I;
  for (std::size_t i = 0; i < b.size(); ++i) {
    I.E += 0.5 * b[i].m * b[i].v.norm2();
    I.Lz += lz(b[i].x, b[i].v, b[i].m);
    for (std::size_t j = i + 1; j < b.size(); ++j)
      I.E -= G * b[i].m * b[j].m / std::sqrt((b[i].x - b[j].x).norm2() + eps * eps);
  }
  return I;
}

Invariants invariants(const Particles& p, double G, double eps) {
  std::vector<Body> b(p.fluid());
  const auto& m = p[Field::Mass];
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = {m[i], p.pos(i), p.vel(i)};
  return invariants(b, G, eps);
}

double fall_time(double r0, double mu) { return 0.5 * kPi * std::sqrt(r0 * r0 * r0 / (2.0 * mu)); }

double fall_separation(double r0, double mu, double t) {
  const double tau = std::sqrt(2.0 * mu / (r0 * r0 * r0)) * t;  // = theta + sin(2 theta)/2, increasing on [0, pi/2]
  double lo = 0.0, hi = 0.5 * kPi;
  for (int it = 0; it < 200 && hi - lo > 1e-17; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid + 0.5 * std::sin(2.0 * mid) < tau ? lo : hi) = mid;
  }
  const double c = std::cos(0.5 * (lo + hi));
  return r0 * c * c;
}

std::unique_ptr<Reference> make_conservation_reference(const std::vector<Body>& initial, double G, double eps) {
  return std::make_unique<Conservation>(initial, G, eps);
}
std::unique_ptr<Reference> make_fall_reference(const std::vector<Body>& initial, double G) {
  return std::make_unique<Fall>(initial, G);
}
std::unique_ptr<Reference> make_kepler_reference(const std::vector<Body>& initial, double G) {
  return std::make_unique<Kepler>(initial, G);
}

}  // namespace sph::scenes
