#include "synthetic_snapshots.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace sph::render::test {

namespace {

void set_range(SnapshotField& f) {
  f.min = *std::min_element(f.values.begin(), f.values.end());
  f.max = *std::max_element(f.values.begin(), f.values.end());
}

// Small deterministic generator (splitmix64) -> uniform in [0,1).
struct Rng {
  std::uint64_t s;
  double next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
};

void resize(Snapshot& s, std::size_t n) {
  s.count = n;
  s.x.assign(n, 0.f);
  s.y.assign(n, 0.f);
  s.z.assign(n, 0.f);
  s.h.assign(n, 0.f);
}

// Exact Sod solution at t = 0.2 (Toro's star state for gamma = 1.4): density and pressure.
constexpr double kG = 1.4, kT = 0.2;
constexpr double kCl = 1.1832159566199232;  // sqrt(gamma p_L / rho_L)
constexpr double kPStar = 0.30313, kUStar = 0.92745, kRho3 = 0.42632, kRho4 = 0.26557, kShock = 1.75216;

void sod_exact(double x, double* rho, double* p) {
  const double xi = x / kT;
  if (xi < -kCl) {
    *rho = 1.0, *p = 1.0;
  } else if (xi < kUStar - kCl * std::pow(kPStar, (kG - 1) / (2 * kG))) {  // rarefaction fan
    const double u = 2.0 / (kG + 1) * (kCl + xi);
    const double c = kCl - 0.5 * (kG - 1) * u;
    *rho = std::pow(c / kCl, 2.0 / (kG - 1));
    *p = std::pow(*rho, kG);
  } else if (xi < kUStar) {
    *rho = kRho3, *p = kPStar;
  } else if (xi < kShock) {
    *rho = kRho4, *p = kPStar;
  } else {
    *rho = 0.125, *p = 0.1;
  }
}

}  // namespace

std::size_t lattice_index(int nx, int i, int j) { return static_cast<std::size_t>(j) * nx + i; }

Snapshot lattice_2d(int nx, int ny) {
  Snapshot s;
  s.scene = "lattice";
  s.dim = 2;
  s.step = 123;
  s.t = 0.2;
  s.bounds = {0, 2, 0, 1, 0, 0};
  resize(s, static_cast<std::size_t>(nx) * ny);
  const float dx = 2.f / nx, dy = 1.f / ny;
  SnapshotField rho{"rho", "density rho", {}, 0, 0}, p{"p", "pressure P", {}, 0, 0};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = lattice_index(nx, i, j);
      s.x[k] = (i + 0.5f) * dx;
      s.y[k] = (j + 0.5f) * dy;
      s.h[k] = 1.2f * dx;
      rho.values.push_back(1.f + s.x[k]);
      p.values.push_back(s.y[k]);
    }
  set_range(rho);
  set_range(p);
  s.fields = {rho, p};
  return s;
}

Snapshot tank_2d(int nx, int ny) {
  Snapshot s = lattice_2d(nx, ny);
  s.scene = "tank";
  s.kind.assign(s.count, 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (j == 0 || i == 0 || i == nx - 1) {
        const std::size_t k = lattice_index(nx, i, j);
        s.kind[k] = 1;
        for (SnapshotField& f : s.fields) f.values[k] = kWallValue;
      }
  for (SnapshotField& f : s.fields) {  // the fluid's range
    f.min = INFINITY;
    f.max = -INFINITY;
    for (std::size_t k = 0; k < s.count; ++k)
      if (!s.is_wall(k)) f.min = std::min(f.min, f.values[k]), f.max = std::max(f.max, f.values[k]);
  }
  return s;
}

Outline circle_outline(std::string label, float cx, float cy, float r, int n) {
  Outline o;
  o.label = std::move(label);
  for (int k = 0; k <= n; ++k) {
    const double a = 6.283185307179586 * k / n;
    o.x.push_back(cx + r * static_cast<float>(std::cos(a)));
    o.y.push_back(cy + r * static_cast<float>(std::sin(a)));
  }
  return o;
}

float sod_exact_rho(float x) {
  double rho = 0, p = 0;
  sod_exact(x, &rho, &p);
  return static_cast<float>(rho);
}

Snapshot sod_profile_1d(int n) {
  Snapshot s;
  s.scene = "sod";
  s.dim = 1;
  s.step = 480;
  s.t = kT;
  s.dt = 4e-4;
  s.bounds = {-0.5f, 0.5f, 0, 0, 0, 0};
  resize(s, static_cast<std::size_t>(n));
  SnapshotField rho{"rho", "density rho", {}, 0, 0}, p{"p", "pressure P", {}, 0, 0};
  const double dx = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    const double x = -0.5 + (i + 0.5) * dx;
    // SPH-like: the exact profile averaged over +-4 dx, with a little ringing behind the shock.
    double r = 0, q = 0;
    for (int k = -4; k <= 4; ++k) {
      double rk = 0, qk = 0;
      sod_exact(x + k * dx, &rk, &qk);
      r += rk / 9.0;
      q += qk / 9.0;
    }
    const double ring = 0.012 * std::exp(-std::abs(x - kShock * kT) / 0.02) * std::sin(x * 900.0);
    s.x[i] = static_cast<float>(x);
    s.h[i] = static_cast<float>(1.3 * dx);
    rho.values.push_back(static_cast<float>(r + ring));
    p.values.push_back(static_cast<float>(q));
  }
  set_range(rho);
  set_range(p);
  s.fields = {rho, p};
  ExactCurve er{"rho", {}, {}}, ep{"p", {}, {}};
  for (int k = 0; k <= 800; ++k) {
    const double x = -0.5 + k / 800.0;
    double r = 0, q = 0;
    sod_exact(x, &r, &q);
    er.x.push_back(static_cast<float>(x));
    er.value.push_back(static_cast<float>(r));
    ep.x.push_back(static_cast<float>(x));
    ep.value.push_back(static_cast<float>(q));
  }
  s.exact = {er, ep};
  return s;
}

Snapshot ball_3d(int n) {
  Snapshot s;
  s.scene = "ball";
  s.dim = 3;
  s.step = 57;
  s.t = 0.75;
  s.bounds = {-1, 1, -1, 1, -1, 1};
  resize(s, static_cast<std::size_t>(n));
  SnapshotField rho{"rho", "density rho", {}, 0, 0}, u{"u", "internal energy u", {}, 0, 0};
  Rng rng{42};
  for (int i = 0; i < n; ++i) {
    // Radius r = q^(3/2) (denser centre, like the Evrard sphere rho ~ 1/r), direction uniform.
    const double r = std::pow(rng.next(), 1.5) * 0.95 + 0.02;
    const double cz = 2.0 * rng.next() - 1.0, phi = 6.283185307179586 * rng.next();
    const double sz = std::sqrt(1.0 - cz * cz);
    s.x[i] = static_cast<float>(r * sz * std::cos(phi));
    s.y[i] = static_cast<float>(r * sz * std::sin(phi));
    s.z[i] = static_cast<float>(r * cz);
    const double density = 1.0 / (2.0 * 3.141592653589793 * r);
    s.h[i] = static_cast<float>(0.12 * std::cbrt(1.0 / (density * n / 400.0)));
    rho.values.push_back(static_cast<float>(density));
    u.values.push_back(static_cast<float>(0.05 * (1.0 + 0.5 * s.z[i])));
  }
  set_range(rho);
  set_range(u);
  s.fields = {rho, u};
  return s;
}

Snapshot random_cloud(int dim, int n) {
  Snapshot s;
  s.scene = "cloud";
  s.dim = dim;
  s.step = 1;
  s.t = 0.0;
  s.bounds = {0, 1, 0, 1, dim == 3 ? 0.f : 0.f, dim == 3 ? 1.f : 0.f};
  resize(s, static_cast<std::size_t>(n));
  SnapshotField rho{"rho", "density rho", {}, 0, 0};
  Rng rng{7};
  const float h = dim == 3 ? std::cbrt(60.f / (4.19f * n)) / 2.f : std::sqrt(30.f / (3.14f * n)) / 2.f;
  for (int i = 0; i < n; ++i) {
    s.x[i] = static_cast<float>(rng.next());
    s.y[i] = static_cast<float>(rng.next());
    if (dim == 3) s.z[i] = static_cast<float>(rng.next());
    s.h[i] = h;
    rho.values.push_back(static_cast<float>(1.0 + std::sin(6.0 * s.x[i]) * std::cos(5.0 * s.y[i])));
  }
  set_range(rho);
  s.fields = {rho};
  return s;
}

Snapshot sod_profile_1d_run_b(int n) {
  Snapshot b = sod_profile_1d(n);
  for (std::size_t i = 0; i < b.count; ++i)
    if (b.x[i] > 0.f && b.x[i] < 0.15f) b.fields.front().values[i] *= 0.8f;
  return b;
}

}  // namespace sph::render::test
