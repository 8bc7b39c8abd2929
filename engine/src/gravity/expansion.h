// Cartesian Taylor expansions of the (Plummer-softened) Newtonian potential g(R) = (R.R + e2)^(-1/2) to
// order P, for the fast multipole method (gravity/fmm.h; Dehnen 2002, J. Comput. Phys. 179, 27, in raw,
// not traceless, moments). Multi-indices k = (i, j, l) with |k| = i + j + l <= P; k! = i! j! l!,
// d^k = dx^i dy^j dz^l, C(k, q) = prod binom(k_c, q_c).
// - Taylor coefficients a_k(R) = D^k g(R) / k!, by the recurrence (|k| = n >= 1; Duan & Krasny 2001):
//     n s a_k + (2n - 1) sum_c R_c a_(k - e_c) + (n - 1) sum_c a_(k - 2 e_c) = 0,   s = R.R + e2.
// - Multipoles of a cell about its centre z_A: M_k = sum_j m_j d_j^k, d_j = x_j - z_A; the field at
//   x = z_A + R is phi(x) = -sum_k (-1)^|k| a_k(R) M_k (per unit G).
// - Local expansion about a sink centre z_B: phi(z_B + y) = -sum_n L_n y^n, with (R0 = z_B - z_A)
//     L_n += sum_{|n| + |k| <= P} (-1)^|k| C(n + k, n) a_(n + k)(R0) M_k            (M2L)
// - Shifts: M'_k = sum_{q <= k} C(k, q) s^(k - q) M_q for a child centre z_A + s (M2M), and
//   L'_q = sum_{n >= q} C(n, q) t^(n - q) L_n for a child centre z_B + t (L2L).
// Each order is its own class with its tables fixed at compile time, so the sums unroll into straight
// multiply-adds: a fixed sequence, the same bits on every run and thread.
#pragma once
#include <cstddef>
#include <memory>

namespace sph::gravity {

class Expansion {
 public:
  static constexpr int kMinOrder = 1, kMaxOrder = 6;
  static constexpr std::size_t kMaxSize = (kMaxOrder + 1) * (kMaxOrder + 2) * (kMaxOrder + 3) / 6;
  virtual ~Expansion() = default;
  virtual int order() const = 0;
  /// Number of coefficients (multi-indices with |k| <= P): (P+1)(P+2)(P+3)/6.
  virtual std::size_t size() const = 0;
  /// a_k(R) for every |k| <= P into a[size()].
  virtual void coefficients(double x, double y, double z, double e2, double* a) const = 0;
  /// M_k += m d^k (a particle of mass m at offset d from the centre).
  virtual void p2m(double m, double dx, double dy, double dz, double* M) const = 0;
  /// Mp += the child's multipoles Mc, whose centre is at s from the parent's.
  virtual void m2m(const double* Mc, double sx, double sy, double sz, double* Mp) const = 0;
  /// L += the local expansion about z_B of the multipoles M about z_A, R0 = z_B - z_A.
  virtual void m2l(const double* M, double rx, double ry, double rz, double e2, double* L) const = 0;
  /// The M2L of four source cells into one L: lanes v = 0..3 (multipoles M[v], offsets R[v]) summed
  /// lane by lane, then L_n += (l_0 + l_1) + (l_2 + l_3). The lanes are a fixed grouping, not the
  /// machine's vector width: the same bits with AVX2, SSE2 or none. An unused lane: M[v] all zero.
  virtual void m2l4(const double* const M[4], const double R[4][3], double e2, double* L) const = 0;
  /// Lc += the parent's expansion Lp shifted to the child's centre, at t from the parent's.
  virtual void l2l(const double* Lp, double tx, double ty, double tz, double* Lc) const = 0;
  /// Adds the potential -sum L_n y^n and the acceleration sum L_n grad(y^n) at offset y from the centre
  /// (per unit G) to phi and a.
  virtual void l2p(const double* L, double yx, double yy, double yz, double& phi, double& ax, double& ay,
                   double& az) const = 0;
  /// Adds the multipoles' potential and acceleration at R from their centre (per unit G) to phi and a.
  virtual void m2p(const double* M, double rx, double ry, double rz, double e2, double& phi, double& ax,
                   double& ay, double& az) const = 0;
  /// m2p at four offsets R[v] at once (lanes v = 0..3 into phi[v], a*[v]): each lane the same operations
  /// in the same order as m2p, so the same bits.
  virtual void m2p4(const double* M, const double R[4][3], double e2, double* phi, double* ax, double* ay,
                    double* az) const = 0;
};

/// The expansion of order P in [kMinOrder, kMaxOrder]; std::invalid_argument beyond.
std::unique_ptr<Expansion> make_expansion(int order);

}  // namespace sph::gravity
