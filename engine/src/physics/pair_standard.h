// The standard force loop's work for one particle a (forces_standard.cpp states the equations), in the
// passes of pair_block.h: the terms of each pair (kernel and geometry, then the momentum, continuity and
// energy terms; vectorised, no reductions), the sums in list order, and the write-back of dv/dt, v_sig,
// du/dt, dh/dt and the fused continuity rate.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/parallel.h"
#include "core/stage.h"
#include "continuity_output.h"
#include "pair_block.h"
#include "pair_fields.h"
#include "pair_terms.h"
#include "terms/conduction.h"
#include "terms/energy_equation.h"

namespace sph::standard {

/// The per-pair columns of the loop's PairBlock.
enum Column { kFx, kFy, kFz, kVs, kDu, kVh, kCond, kLx, kLy, kLz, kDrho, kDiff, kCount, kColumns };
using Block = PairBlock<kColumns>;

/// A block's columns, taken once before the pair loops.
struct Columns {
  double *FX, *FY, *FZ, *VS, *DU, *VH, *CD, *LX, *LY, *LZ, *DR, *DF, *CN;
  explicit Columns(Block& b)
      : FX(b[kFx]), FY(b[kFy]), FZ(b[kFz]), VS(b[kVs]), DU(b[kDu]), VH(b[kVh]), CD(b[kCond]), LX(b[kLx]),
        LY(b[kLy]), LZ(b[kLz]), DR(b[kDrho]), DF(b[kDiff]), CN(b[kCount]) {}
};

/// Per-particle factors of the pair loop, kept between evaluations (no reallocation).
struct Factors {
  std::vector<double> hinv, dnorm, A, R2;

  /// Once per evaluation (ghosts included): 1/h, sigma/h^(d+1) of dW/dr, A = P/(Omega rho^2) and
  /// (support h)^2.
  template <bool GradH>
  void compute(Particles& p, const Kernel& K) {
    const ForceFields f(p);
    const double* omega = GradH ? p[Field::Omega].data() : nullptr;
    const std::size_t total = p.total();
    const int d = p.dim();
    hinv.resize(total);
    dnorm.resize(total);
    A.resize(total);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
    for (std::size_t j = 0; j < total; ++j) {
      const double s = 1.0 / f.h[j];
      double hd = s * s;
      for (int k = 1; k < d; ++k) hd *= s;
      hinv[j] = s;
      dnorm[j] = K.sigma() * hd;
      A[j] = pressure_factor(f.P[j], GradH ? omega[j] : 1.0, f.rho[j]);
    }
    support_radii2(p, K.support(), R2);
  }
};

/// Particle a's own values, loaded once for its pairs.
struct Self {
  std::size_t i;
  double vx, vy, vz, h, hinv, dnorm, A, rho, cs;
};

/// The kernel and geometry of pair (a, j): r_aj, |r|, 1/|r|, dW/dr at h_a, h_j and their mean, v_aj,
/// v_aj . r_aj and w = v_aj . r_hat.
struct Geometry {
  std::uint32_t j;
  double dx, dy, dz, r2, r, rinv, dWi, dWj, dWm, dvx, dvy, dvz, vdotr, w;
};

/// The viscosity term's pair values: Pi_ab (kPi) and the Laplacian factor k_ab (kLaplacian). Like Geometry
/// it is built from values and passed by value in the pair loop: an aggregate whose address is taken there
/// (a reference argument, a named object filled member by member and returned) becomes one copy per lane
/// in memory under `omp simd`, and GCC 12 then did not vectorise the loop (2.5x the force loop's time per
/// neighbour).
struct ViscPair {
  double Pi = 0.0, lap = 0.0;
};

/// The sums over a's pairs.
struct Sums {
  double ax = 0.0, ay = 0.0, az = 0.0, du = 0.0, visc_heat = 0.0, cond = 0.0;
  double vs;  ///< v_sig: starts at c_s,a
  double drho = 0.0, diff = 0.0;
  int count = 1;
};

/// V: the viscosity term (terms/visc_*.h); E: the energy equation on or off (terms/energy_equation.h);
/// Cont: the continuity rate in the same pass; ThreeD = false in 1D and 2D (no z terms).
template <bool GradH, class V, class E, bool Cont, bool ThreeD, class Shape>
struct Pairs {
  using Block = standard::Block;
  static constexpr int kColumns = standard::kColumns;
  static constexpr bool kThreeD = ThreeD, kCont = Cont;
  static constexpr bool Energy = E::kOn;
  const Shape shape;
  const V visc;
  const terms::Conduction cond_term;
  const ForceFields f;
  const double *vx, *vy, *vz, *hinv, *dnorm, *pA;
  const std::uint8_t* kind;
  const double* omega;  ///< Omega (grad-h) or null
  const double* u;      ///< internal energy (energy equation) or null
  double* dudt;         ///< du/dt (energy equation) or null
  double* hrate;        ///< dh/dt of a summation density with a Newton-Raphson h: the next solve's first guess
  double* a[3];         ///< dv/dt
  const double* xs[3] = {nullptr, nullptr, nullptr};  ///< XSPH corrections v* - v
  double support;
  bool conduction, xsph;
  int d;

  Pairs(StageContext& c, const Shape& s, const Factors& fac)
      : shape(s), visc(c), cond_term(c), f(c.p), vx(c.p.v[0].data()), vy(c.p.v[1].data()), vz(c.p.v[2].data()),
        hinv(fac.hinv.data()), dnorm(fac.dnorm.data()), pA(fac.A.data()), kind(c.p.kind.data()),
        omega(GradH ? c.p[Field::Omega].data() : nullptr), u(Energy ? c.p[Field::Energy].data() : nullptr),
        dudt(Energy ? c.p[Field::EnergyRate].data() : nullptr),
        hrate(GradH && c.p.has(Field::HRate) ? c.p[Field::HRate].data() : nullptr),
        a{c.p.a[0].data(), c.p.a[1].data(), c.p.a[2].data()}, support(c.kernel.support()),
        conduction(Energy && cond_term.on), xsph(Cont && c.prm.physics.xsph == Toggle::On), d(c.p.dim()) {
    if (xsph)
      for (int k = 0; k < 3; ++k) xs[k] = c.p[component(Field::XsphX, k)].data();
  }

  Self self(std::size_t i) const {
    return Self{i, vx[i], vy[i], ThreeD ? vz[i] : 0.0, f.h[i], hinv[i], dnorm[i], pA[i], f.rho[i], f.cs[i]};
  }

  /// The pair's kernel derivatives (dW/dr = sigma dw/dq (r/h) / h^(d+1); grad W = r_hat dW/dr) and v_aj.
  [[gnu::always_inline]] Geometry geometry(const Self& s, std::uint32_t j, double dx, double dy, double dz,
                                           double r2) const {
    const double r = std::sqrt(r2);
    const double rinv = 1.0 / r;
    const double dWi = s.dnorm * shape.dw(r * s.hinv), dWj = dnorm[j] * shape.dw(r * hinv[j]);
    const double dvx = s.vx - vx[j], dvy = s.vy - vy[j], dvz = ThreeD ? s.vz - vz[j] : 0.0;
    const double vdotr = ThreeD ? dvx * dx + dvy * dy + dvz * dz : dvx * dx + dvy * dy;
    return Geometry{j, dx, dy, dz, r2, r, rinv, dWi, dWj, 0.5 * (dWi + dWj), dvx, dvy, dvz, vdotr, vdotr * rinv};
  }

  /// The viscosity term's pair values: Pi_ab (kPi) and the Laplacian factor k_ab (kLaplacian); 0 without.
  [[gnu::always_inline]] double pi(const Self& s, const Geometry g) const {
    if constexpr (V::kPi) return visc.pi(s.i, g.j, g.vdotr, g.r2, s.h, f.h[g.j], s.rho, f.rho[g.j], s.cs, f.cs[g.j]);
    return 0.0;
  }
  [[gnu::always_inline]] double laplacian(const Self& s, const Geometry g) const {
    const std::uint32_t j = g.j;
    if constexpr (V::kLaplacian) return visc.factor(j, f.m[j], s.rho, f.rho[j], g.r * g.dWm, g.r2, 0.5 * (s.h + f.h[j]));
    return 0.0;
  }

  /// The pair's dv_a/dt (pressure, Pi, Laplacian) and signal speed, into column k.
  [[gnu::always_inline]] void momentum(const Self& s, const Geometry g, const ViscPair vp, const Columns& o,
                                       std::size_t k) const {
    const std::uint32_t j = g.j;
    o.VS[k] = pair::signal_speed(s.cs, f.cs[j], g.w, visc.alpha_scale, visc.beta_scale);
    const double Aj = pA[j];
    const double fr = V::kPi ? -f.m[j] * (s.A * g.dWi + Aj * g.dWj + vp.Pi * g.dWm) * g.rinv
                             : -f.m[j] * (s.A * g.dWi + Aj * g.dWj) * g.rinv;  // times r_vec
    o.FX[k] = fr * g.dx;
    o.FY[k] = fr * g.dy;
    if constexpr (ThreeD) o.FZ[k] = fr * g.dz;
    if constexpr (V::kLaplacian) {
      o.LX[k] = vp.lap * g.dvx;
      o.LY[k] = vp.lap * g.dvy;
      if constexpr (ThreeD) o.LZ[k] = vp.lap * g.dvz;
    }
  }

  /// The pair's share of the continuity rate, V_j (v*_a - v*_j) . grad W_aj(h_a), its density diffusion
  /// and whether j is within a's own support.
  [[gnu::always_inline]] void continuity(const Self& s, const Geometry g, const Columns& o, std::size_t k) const {
    const std::uint32_t j = g.j;
    const std::size_t i = s.i;
    o.CN[k] = g.r2 < support * support * s.h * s.h ? 1.0 : 0.0;
    double ddx = g.dvx, ddy = g.dvy, ddz = g.dvz;  // v*_a - v*_b
    if (xsph) {
      const bool fluid_j = !kind[j];
      ddx += xs[0][i] - (fluid_j ? xs[0][j] : 0.0);
      ddy += xs[1][i] - (fluid_j ? xs[1][j] : 0.0);
      if constexpr (ThreeD) ddz += xs[2][i] - (fluid_j ? xs[2][j] : 0.0);
    }
    const double Vj = f.m[j] / f.rho[j], dW_r = g.dWi * g.rinv;
    o.DR[k] = Vj * (ThreeD ? ddx * g.dx + ddy * g.dy + ddz * g.dz : ddx * g.dx + ddy * g.dy) * dW_r;
    o.DF[k] = pair::density_diffusion(Vj, s.rho, f.rho[j], dW_r);
  }

  /// The pair's energy terms: sum_b m_b v_ab . grad W_ab(h_a) (also dh/dt's) and the viscous heating.
  [[gnu::always_inline]] void energy(const Geometry g, const ViscPair vp, const Columns& o, std::size_t k) const {
    if constexpr (Energy || GradH) o.DU[k] = terms::EnergyOn::pair(f.m[g.j], g.w, g.dWi);
    if constexpr (Energy) {  // du/dt = Ai times that sum (seed 000 eq. 3.3.19)
      if constexpr (V::kPi) o.VH[k] = V::heat(f.m[g.j], vp.Pi, g.w, g.dWm);  // dissipation -> heat
      // the Laplacian term's work -k v_ab . v_ab / 2 per pair share, as heat
      if constexpr (V::kLaplacian)
        o.VH[k] = V::work(vp.lap, ThreeD ? g.dvx * g.dvx + g.dvy * g.dvy + g.dvz * g.dvz
                                           : g.dvx * g.dvx + g.dvy * g.dvy);
    }
  }

  /// The terms of a's np pairs, per pair, with no reduction: vectorised.
  void terms(const Self& s, Block& b, std::size_t np) const {
    const std::uint32_t* J = b.j.data();
    const double* DX = b.dx.data();
    const double* DY = b.dy.data();
    const double* DZ = b.dz.data();
    const double* R2 = b.r2.data();
    const Columns o(b);
#pragma omp simd
    for (std::size_t k = 0; k < np; ++k) {
      const Geometry g = geometry(s, J[k], DX[k], DY[k], ThreeD ? DZ[k] : 0.0, R2[k]);
      const ViscPair vp{pi(s, g), laplacian(s, g)};
      momentum(s, g, vp, o, k);
      if constexpr (Cont) continuity(s, g, o, k);
      energy(g, vp, o, k);
    }
    if (conduction) conduction_terms(s, b, np);
  }

  /// Conduction's du_a/dt per pair (terms/conduction.h), in a pass of its own.
  void conduction_terms(const Self& s, Block& b, std::size_t np) const {
    const std::uint32_t* J = b.j.data();
    const double* R2 = b.r2.data();
    double* CD = b[kCond];
    const double Pi_ = f.P[s.i], ui = u[s.i];
#pragma omp simd
    for (std::size_t k = 0; k < np; ++k) {
      const std::uint32_t j = J[k];
      const double r = std::sqrt(R2[k]);
      const double dWm = 0.5 * (s.dnorm * shape.dw(r * s.hinv) + dnorm[j] * shape.dw(r * hinv[j]));
      CD[k] = cond_term.pair(f.m[j], ui, u[j], Pi_, f.P[j], s.rho, f.rho[j], dWm);
    }
  }

  /// The sums of the columns, in list order.
  Sums sum(const Self& s, Block& b, std::size_t np) const {
    const Columns o(b);
    Sums t;
    t.vs = s.cs;
    for (std::size_t k = 0; k < np; ++k) {
      t.ax += o.FX[k];
      t.ay += o.FY[k];
      if constexpr (ThreeD) t.az += o.FZ[k];
      if constexpr (V::kLaplacian) {
        t.ax += o.LX[k];
        t.ay += o.LY[k];
        if constexpr (ThreeD) t.az += o.LZ[k];
      }
      t.vs = std::max(t.vs, o.VS[k]);
      if constexpr (Cont) {
        t.count += static_cast<int>(o.CN[k]);
        t.drho += o.DR[k];
        t.diff += o.DF[k];
      }
      if constexpr (Energy || GradH) t.du += o.DU[k];
      if constexpr (Energy) {
        if constexpr (V::kPi) t.visc_heat += o.VH[k];
        if constexpr (V::kLaplacian) t.visc_heat -= o.VH[k];
      }
    }
    if (conduction)
      for (std::size_t k = 0; k < np; ++k) t.cond += o.CD[k];
    return t;
  }

  /// a's results from its sums: dv/dt, v_sig, du/dt, dh/dt and the continuity rate.
  void finish(const Self& s, const Sums& t, const ContinuityOutput* cont) const {
    const std::size_t i = s.i;
    a[0][i] = t.ax;
    a[1][i] = t.ay;
    a[2][i] = t.az;
    f.vsig[i] = t.vs;
    if constexpr (Energy) dudt[i] = E::rate(s.A, t.du, t.visc_heat, t.cond);
    // drho/dt = (1/Omega) sum_b m_b v_ab . grad W_ab(h_a), and h = eta (m/rho)^(1/d) gives
    // dh/dt = -h/(d rho) drho/dt (seed 000 eqs. 3.3.2, 3.5.1)
    if (hrate) hrate[i] = -s.h / (d * s.rho) * (t.du / omega[i]);
    if constexpr (Cont) cont->store(i, s.rho, s.h, t.drho, t.diff, t.count);
  }
};

}  // namespace sph::standard
