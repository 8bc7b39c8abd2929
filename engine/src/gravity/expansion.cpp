// Cartesian Taylor expansions of the softened 1/r potential (gravity/expansion.h): for each order, the
// multi-index tables built at compile time and the operations as fully unrolled sums over them.
#include "gravity/expansion.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace sph::gravity {
namespace {

/// One term of a table-driven sum: out[o] += coef * w[p] * in[i].
struct Term {
  int out, in, pw;
  double coef;
};

struct Index {
  int i, j, l, n;
};

constexpr double binom(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

template <int P>
struct Tables {
  static constexpr int N = (P + 1) * (P + 2) * (P + 3) / 6;
  /// by degree, then lexicographic: a coefficient's lower ones come first; 1, 2, 3 are x, y, z
  static constexpr std::array<Index, N> idx = [] {
    std::array<Index, N> a{};
    int c = 0;
    for (int n = 0; n <= P; ++n)
      for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) a[c++] = {i, j, n - i - j, n};
    return a;
  }();
  static constexpr int find(int i, int j, int l) {
    if (i < 0 || j < 0 || l < 0 || i + j + l > P) return -1;
    for (int c = 0; c < N; ++c)
      if (idx[c].i == i && idx[c].j == j && idx[c].l == l) return c;
    return -1;
  }
  /// The shift terms: M2M (out k, in q, power k - q) for every q <= k; L2L swaps out and in.
  static constexpr int kShift = [] {
    int c = 0;
    for (const Index& k : idx)
      for (const Index& q : idx) c += q.i <= k.i && q.j <= k.j && q.l <= k.l;
    return c;
  }();
  static constexpr std::array<Term, kShift> shift = [] {
    std::array<Term, kShift> t{};
    int c = 0;
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b) {
        const Index k = idx[a], q = idx[b];
        if (q.i <= k.i && q.j <= k.j && q.l <= k.l)
          t[c++] = {a, b, find(k.i - q.i, k.j - q.j, k.l - q.l), binom(k.i, q.i) * binom(k.j, q.j) * binom(k.l, q.l)};
      }
    return t;
  }();
  /// M2L: out n, in multipole k, coefficient a_(n + k), for |n| + |k| <= P
  static constexpr int kM2L = [] {
    int c = 0;
    for (const Index& k : idx)
      for (const Index& q : idx) c += k.n + q.n <= P;
    return c;
  }();
  static constexpr std::array<Term, kM2L> m2l = [] {
    std::array<Term, kM2L> t{};
    int c = 0;
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b) {
        const Index n = idx[a], k = idx[b];
        if (n.n + k.n > P) continue;
        const double sign = k.n % 2 == 0 ? 1.0 : -1.0;
        t[c++] = {a, b, find(n.i + k.i, n.j + k.j, n.l + k.l),
                  sign * binom(n.i + k.i, n.i) * binom(n.j + k.j, n.j) * binom(n.l + k.l, n.l)};
      }
    return t;
  }();
  /// The recurrence of a_k: k - e_c and k - 2 e_c (c = x, y, z; -1 when negative), (2n - 1)/n, (n - 1)/n
  struct Down {
    int d1[3], d2[3];
    double f1, f2;
  };
  static constexpr std::array<Down, N> down = [] {
    std::array<Down, N> d{};
    for (int c = 1; c < N; ++c) {
      const Index k = idx[c];
      d[c] = {{find(k.i - 1, k.j, k.l), find(k.i, k.j - 1, k.l), find(k.i, k.j, k.l - 1)},
              {find(k.i - 2, k.j, k.l), find(k.i, k.j - 2, k.l), find(k.i, k.j, k.l - 2)},
              (2.0 * k.n - 1.0) / k.n,
              (k.n - 1.0) / k.n};
    }
    return d;
  }();
};

template <int P>
class ExpansionOf final : public Expansion {
  using T = Tables<P>;
  static constexpr int N = T::N;

 public:
  int order() const override { return P; }
  std::size_t size() const override { return N; }

  void coefficients(double x, double y, double z, double e2, double* a) const override {
    const double inv_s = 1.0 / (x * x + y * y + z * z + e2), R[3] = {x, y, z};
    a[0] = std::sqrt(inv_s);
#pragma GCC unroll 128
    for (int c = 1; c < N; ++c) {
      const auto& d = T::down[c];
      double first = 0.0, second = 0.0;
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k) {
        if (d.d1[k] >= 0) first += R[k] * a[d.d1[k]];
        if (d.d2[k] >= 0) second += a[d.d2[k]];
      }
      a[c] = -(d.f1 * first + d.f2 * second) * inv_s;
    }
  }
  void p2m(double m, double dx, double dy, double dz, double* M) const override {
    double pw[N];
    powers(dx, dy, dz, pw);
    for (int c = 0; c < N; ++c) M[c] += m * pw[c];
  }
  void m2m(const double* Mc, double sx, double sy, double sz, double* Mp) const override {
    double pw[N];
    powers(sx, sy, sz, pw);
#pragma GCC unroll 2048
    for (int t = 0; t < T::kShift; ++t) Mp[T::shift[t].out] += T::shift[t].coef * pw[T::shift[t].pw] * Mc[T::shift[t].in];
  }
  void m2l(const double* M, double rx, double ry, double rz, double e2, double* L) const override {
    // on local copies: no store can alias a load, so the unrolled sums schedule freely
    double a[N], m[N], l[N] = {};
    coefficients(rx, ry, rz, e2, a);
    for (int c = 0; c < N; ++c) m[c] = M[c];
#pragma GCC unroll 2048
    for (int t = 0; t < T::kM2L; ++t) l[T::m2l[t].out] += T::m2l[t].coef * a[T::m2l[t].pw] * m[T::m2l[t].in];
    for (int c = 0; c < N; ++c) L[c] += l[c];
  }
  void m2l4(const double* const M[4], const double R[4][3], double e2, double* L) const override {
    double a[N][4], m[N][4], l[N][4] = {};
    lane_coefficients(R, e2, a);
    for (int c = 0; c < N; ++c)
      for (int v = 0; v < 4; ++v) m[c][v] = M[v][c];
#pragma GCC unroll 2048
    for (int t = 0; t < T::kM2L; ++t) {
      const Term& u = T::m2l[t];
      for (int v = 0; v < 4; ++v) l[u.out][v] += u.coef * a[u.pw][v] * m[u.in][v];
    }
    for (int c = 0; c < N; ++c) L[c] += (l[c][0] + l[c][1]) + (l[c][2] + l[c][3]);
  }
  void l2l(const double* Lp, double tx, double ty, double tz, double* Lc) const override {
    double pw[N];
    powers(tx, ty, tz, pw);
#pragma GCC unroll 2048
    for (int t = 0; t < T::kShift; ++t)
      Lc[T::shift[t].in] += T::shift[t].coef * pw[T::shift[t].pw] * Lp[T::shift[t].out];
  }
  void l2p(const double* L, double yx, double yy, double yz, double& phi, double& ax, double& ay,
           double& az) const override {
    double pw[N];
    powers(yx, yy, yz, pw);
    double p = 0.0, g[3] = {0.0, 0.0, 0.0};
#pragma GCC unroll 128
    for (int c = 0; c < N; ++c) {
      p += L[c] * pw[c];
      const int e[3] = {T::idx[c].i, T::idx[c].j, T::idx[c].l};
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k)
        if (T::down[c].d1[k] >= 0) g[k] += L[c] * e[k] * pw[T::down[c].d1[k]];
    }
    phi -= p;
    ax += g[0];
    ay += g[1];
    az += g[2];
  }
  void m2p(const double* M, double rx, double ry, double rz, double e2, double& phi, double& ax, double& ay,
           double& az) const override {
    double a[N], L[4] = {0.0, 0.0, 0.0, 0.0};
    coefficients(rx, ry, rz, e2, a);
#pragma GCC unroll 2048
    for (int t = 0; t < T::kM2L; ++t)  // the terms of L_0 and L_(e_c) only
      if (T::m2l[t].out < 4) L[T::m2l[t].out] += T::m2l[t].coef * a[T::m2l[t].pw] * M[T::m2l[t].in];
    phi -= L[0];
    ax += L[1];
    ay += L[2];
    az += L[3];
  }
  void m2p4(const double* M, const double R[4][3], double e2, double* phi, double* ax, double* ay,
            double* az) const override {
    double a[N][4], l[4][4] = {};
    lane_coefficients(R, e2, a);
#pragma GCC unroll 2048
    for (int t = 0; t < T::kM2L; ++t) {  // the terms of L_0 and L_(e_c) only, as m2p
      const Term& u = T::m2l[t];
      if (u.out < 4)
        for (int v = 0; v < 4; ++v) l[u.out][v] += u.coef * a[u.pw][v] * M[u.in];
    }
    for (int v = 0; v < 4; ++v) {
      phi[v] -= l[0][v];
      ax[v] += l[1][v];
      ay[v] += l[2][v];
      az[v] += l[3][v];
    }
  }

 private:
  /// coefficients() at four offsets, lane by lane (the same operations in the same order per lane).
  static void lane_coefficients(const double R[4][3], double e2, double a[N][4]) {
    double inv_s[4];
    for (int v = 0; v < 4; ++v) {
      inv_s[v] = 1.0 / (R[v][0] * R[v][0] + R[v][1] * R[v][1] + R[v][2] * R[v][2] + e2);
      a[0][v] = std::sqrt(inv_s[v]);
    }
#pragma GCC unroll 128
    for (int c = 1; c < N; ++c) {
      const auto& d = T::down[c];
      double first[4] = {}, second[4] = {};
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k) {
        if (d.d1[k] >= 0)
          for (int v = 0; v < 4; ++v) first[v] += R[v][k] * a[d.d1[k]][v];
        if (d.d2[k] >= 0)
          for (int v = 0; v < 4; ++v) second[v] += a[d.d2[k]][v];
      }
      for (int v = 0; v < 4; ++v) a[c][v] = -(d.f1 * first[v] + d.f2 * second[v]) * inv_s[v];
    }
  }
  static void powers(double x, double y, double z, double* pw) {
    double px[P + 1], py[P + 1], pz[P + 1];
    px[0] = py[0] = pz[0] = 1.0;
    for (int k = 1; k <= P; ++k) {
      px[k] = px[k - 1] * x;
      py[k] = py[k - 1] * y;
      pz[k] = pz[k - 1] * z;
    }
#pragma GCC unroll 128
    for (int c = 0; c < N; ++c) pw[c] = px[T::idx[c].i] * py[T::idx[c].j] * pz[T::idx[c].l];
  }
};

}  // namespace

std::unique_ptr<Expansion> make_expansion(int order) {
  switch (order) {
    case 1: return std::make_unique<ExpansionOf<1>>();
    case 2: return std::make_unique<ExpansionOf<2>>();
    case 3: return std::make_unique<ExpansionOf<3>>();
    case 4: return std::make_unique<ExpansionOf<4>>();
    case 5: return std::make_unique<ExpansionOf<5>>();
    case 6: return std::make_unique<ExpansionOf<6>>();
    default: throw std::invalid_argument("gravity expansion order must be in [1, 6]");
  }
}

}  // namespace sph::gravity
