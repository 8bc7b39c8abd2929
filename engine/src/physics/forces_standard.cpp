// The standard momentum equation, with its fused viscosity, conduction and energy terms:
//   dv_a/dt = -sum_b m_b [P_a/(Omega_a rho_a^2) grad W_ab(h_a) + P_b/(Omega_b rho_b^2) grad W_ab(h_b)
//                         + Pi_ab grad W_ab(mean)]                    (seed 000 eq. 3.3.17; seed 001 eq. 44)
//   du_a/dt = P_a/(Omega_a rho_a^2) sum_b m_b v_ab . grad W_ab(h_a)    (seed 000 eq. 3.3.19)
//           + 1/2 sum_b m_b Pi_ab v_ab . grad W_ab(mean)          (viscous heating: energy conserved)
//           + sum_b m_b alpha_u v_sig,u (u_a - u_b)/rho_ab r_hat . grad W_ab(mean) (Price 2008 conduction)
// Omega = 1 without a summation density (continuity densities have no grad-h terms). The Laplacian
// viscosity adds sum_b m_b (mu_a + mu_b)/(rho_a rho_b) (r.grad W)/(r^2 + eps h^2) v_ab (Morris 1997).
// A gather over the neighbour list: each particle sums its own neighbours in list order.
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "core/stages.h"
#include "courant.h"
#include "continuity_output.h"
#include "pair_block.h"
#include "pair_terms.h"
#include "sph/kernel_shapes.h"
#include "terms/conduction.h"
#include "terms/energy_equation.h"
#include "terms/visc_terms.h"

namespace sph {
namespace {

/// The per-pair columns of the loop's PairBlock.
enum Column { kFx, kFy, kFz, kVs, kDu, kVh, kCond, kLx, kLy, kLz, kDrho, kDiff, kCount, kColumns };

/// Per-particle factors of the pair loop, kept between evaluations (no reallocation).
struct Factors {
  std::vector<double> hinv, dnorm, A, R2;
};

/// V: the viscosity term (terms/visc_*.h); E: the energy equation on or off (terms/energy_equation.h).
/// Cont: also the continuity rate drho_a/dt = rho_a sum_b V_b (v*_a - v*_b) . grad W_ab(h_a) with its
/// density diffusion (density_continuity.cpp), in the same pass (barotropic flows only). Shape: the
/// kernel's shape, fixed at compile time (one instantiation per kernel, chosen once per evaluation).
/// ThreeD = false in 1D and 2D, where z and v_z are 0: the z terms are not computed (each would add
/// +-0 to a sum; the results differ at most in the sign of an exact zero).

template <bool GradH, class V, class E, bool Cont, bool ThreeD, class Shape>
void standard_loop(StageContext& c, const Shape& shape, Factors& fac) {
  constexpr bool Energy = E::kOn;
  const Kernel& K = c.kernel;
  const Params& prm = c.prm;
  Particles& p = c.p;
  const std::size_t n = p.fluid();
  const auto& m = p[Field::Mass];
  const auto& rho = p[Field::Density];
  const auto& h = p[Field::H];
  const std::vector<double>* omega = GradH ? &p[Field::Omega] : nullptr;
  const auto& P = p[Field::Pressure];
  const auto& cs = p[Field::SoundSpeed];
  auto& vsig = p[Field::SignalSpeed];
  const std::vector<double>* u = Energy ? &p[Field::Energy] : nullptr;
  std::vector<double>* dudt = Energy ? &p[Field::EnergyRate] : nullptr;
  // dh/dt of a summation density with a Newton-Raphson h: the next solve's first guess (density_summation)
  double* hrate = GradH && p.has(Field::HRate) ? p[Field::HRate].data() : nullptr;
  const terms::Conduction cond_term(c);
  const bool conduction = Energy && cond_term.on;
  const bool skip_walls = prm.physics.walls == WallType::LennardJones;
  const V visc(c);
  const double support = K.support();
  std::unique_ptr<ContinuityOutput> cont;
  if constexpr (Cont) cont = std::make_unique<ContinuityOutput>(p, prm);
  const bool xsph = Cont && prm.physics.xsph == Toggle::On;
  const double* xs[3] = {nullptr, nullptr, nullptr};  // XSPH corrections v* - v
  if (xsph)
    for (int k = 0; k < 3; ++k) xs[k] = p[component(Field::XsphX, k)].data();
  double sum_nb = 0.0;
  // per-particle factors, once per evaluation (ghosts included): 1/h, sigma/h^(d+1) of dW/dr, and
  // A = P/(Omega rho^2)
  const std::size_t total = p.total();
  const int d = p.dim();
  fac.hinv.resize(total);
  fac.dnorm.resize(total);
  fac.A.resize(total);
  fac.R2.resize(total);
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t j = 0; j < total; ++j) {
    const double s = 1.0 / h[j];
    double hd = s * s;
    for (int k = 1; k < d; ++k) hd *= s;
    fac.hinv[j] = s;
    fac.dnorm[j] = K.sigma() * hd;
    fac.A[j] = GradH ? P[j] / ((*omega)[j] * rho[j] * rho[j]) : P[j] / (rho[j] * rho[j]);
    const double R = support * h[j];
    fac.R2[j] = R * R;
  }
  const double* hinv = fac.hinv.data();
  const double* vx = p.v[0].data();
  const double* vy = p.v[1].data();
  const double* vz = p.v[2].data();
  const std::uint8_t* kind = p.kind.data();
  const double* dnorm = fac.dnorm.data();
  const double* pA = fac.A.data();

#pragma omp parallel reduction(+ : sum_nb) if (p.size() >= kParallelMin)
  {
  PairBlock<kColumns> b;  // this thread's pairs of i
#pragma omp for schedule(static)  // the same block per thread in every loop (core/parallel.h)
  for (std::size_t i = 0; i < n; ++i) {
    const double vxi = p.v[0][i], vyi = p.v[1][i], vzi = ThreeD ? p.v[2][i] : 0.0;
    const double hi = h[i], hinv_i = hinv[i], dnorm_i = dnorm[i];
    const double Ai = pA[i], rhoi = rho[i], csi = cs[i];
    const std::size_t np = gather_pairs<kColumns, ThreeD>(p, fac.R2.data(), i, c.nl.of(i), skip_walls, b);
    const std::uint32_t* J = b.j.data();
    const double* DX = b.dx.data();
    const double* DY = b.dy.data();
    const double* DZ = b.dz.data();
    const double* R2 = b.r2.data();
    double* FX = b[kFx]; double* FY = b[kFy]; double* FZ = b[kFz]; double* VS = b[kVs];
    double* DU = b[kDu]; double* VH = b[kVh]; double* LX = b[kLx]; double* LY = b[kLy]; double* LZ = b[kLz];
    double* DR = b[kDrho]; double* DF = b[kDiff]; double* CN = b[kCount];
    // the pair terms, per pair, with no reduction: vectorised
#pragma omp simd
    for (std::size_t k = 0; k < np; ++k) {
      const std::uint32_t j = J[k];
      const double dx = DX[k], dy = DY[k], dz = ThreeD ? DZ[k] : 0.0, r2 = R2[k];
      const double hj = h[j];
      const double r = std::sqrt(r2);
      const double rinv = 1.0 / r;
      // dW/dr = sigma dw/dq (r/h) / h^(d+1); grad W = r_hat dW/dr
      const double dWi = dnorm_i * shape.dw(r * hinv_i), dWj = dnorm[j] * shape.dw(r * hinv[j]);
      const double dWm = 0.5 * (dWi + dWj);
      const double Aj = pA[j];
      const double dvx = vxi - vx[j], dvy = vyi - vy[j], dvz = ThreeD ? vzi - vz[j] : 0.0;
      const double vdotr = ThreeD ? dvx * dx + dvy * dy + dvz * dz : dvx * dx + dvy * dy;
      const double w = vdotr * rinv;
      VS[k] = pair::signal_speed(csi, cs[j], w, visc.alpha_scale, visc.beta_scale);
      double Pi = 0.0;
      if constexpr (V::kPi) Pi = visc.pi(i, j, vdotr, r2, hi, hj, rhoi, rho[j], csi, cs[j]);
      const double f = V::kPi ? -m[j] * (Ai * dWi + Aj * dWj + Pi * dWm) * rinv
                              : -m[j] * (Ai * dWi + Aj * dWj) * rinv;  // times r_vec
      FX[k] = f * dx;
      FY[k] = f * dy;
      if constexpr (ThreeD) FZ[k] = f * dz;
      double lap = 0.0;
      if constexpr (V::kLaplacian) {
        lap = visc.factor(m[j], rhoi, rho[j], r * dWm, r2, 0.5 * (hi + hj));
        LX[k] = lap * dvx;
        LY[k] = lap * dvy;
        if constexpr (ThreeD) LZ[k] = lap * dvz;
      }
      if constexpr (Cont) {
        CN[k] = r2 < support * support * hi * hi ? 1.0 : 0.0;
        double ddx = dvx, ddy = dvy, ddz = dvz;  // v*_a - v*_b
        if (xsph) {
          const bool fluid_j = !kind[j];
          ddx += xs[0][i] - (fluid_j ? xs[0][j] : 0.0);
          ddy += xs[1][i] - (fluid_j ? xs[1][j] : 0.0);
          if constexpr (ThreeD) ddz += xs[2][i] - (fluid_j ? xs[2][j] : 0.0);
        }
        const double Vj = m[j] / rho[j], dW_r = dWi * rinv;
        DR[k] = Vj * (ThreeD ? ddx * dx + ddy * dy + ddz * dz : ddx * dx + ddy * dy) * dW_r;
        DF[k] = pair::density_diffusion(Vj, rhoi, rho[j], dW_r);
      }
      if constexpr (Energy || GradH) DU[k] = terms::EnergyOn::pair(m[j], w, dWi);  // sum_b m_b v_ab . grad W_ab(h_a)
      if constexpr (Energy) {  // du/dt = Ai times that sum (seed 000 eq. 3.3.19)
        if constexpr (V::kPi) VH[k] = V::heat(m[j], Pi, w, dWm);  // dissipation -> heat
        // the Laplacian term's work -k v_ab . v_ab / 2 per pair share, as heat
        if constexpr (V::kLaplacian)
          VH[k] = V::work(lap, ThreeD ? dvx * dvx + dvy * dvy + dvz * dvz : dvx * dvx + dvy * dvy);
      }
    }
    double* CD = b[kCond];
    if (conduction) {
      const double Pi_ = P[i], ui = (*u)[i];
      const double* uu = u->data();
#pragma omp simd
      for (std::size_t k = 0; k < np; ++k) {
        const std::uint32_t j = J[k];
        const double r = std::sqrt(R2[k]);
        const double dWm = 0.5 * (dnorm_i * shape.dw(r * hinv_i) + dnorm[j] * shape.dw(r * hinv[j]));
        CD[k] = cond_term.pair(m[j], ui, uu[j], Pi_, P[j], rhoi, rho[j], dWm);
      }
    }
    // the sums, in list order
    double ax = 0.0, ay = 0.0, az = 0.0, du = 0.0, visc_heat = 0.0, cond = 0.0;
    double vs = csi;
    double drho = 0.0, diff = 0.0;
    int count = 1;
    for (std::size_t k = 0; k < np; ++k) {
      ax += FX[k];
      ay += FY[k];
      if constexpr (ThreeD) az += FZ[k];
      if constexpr (V::kLaplacian) {
        ax += LX[k];
        ay += LY[k];
        if constexpr (ThreeD) az += LZ[k];
      }
      vs = std::max(vs, VS[k]);
      if constexpr (Cont) {
        count += static_cast<int>(CN[k]);
        drho += DR[k];
        diff += DF[k];
      }
      if constexpr (Energy || GradH) du += DU[k];
      if constexpr (Energy) {
        if constexpr (V::kPi) visc_heat += VH[k];
        if constexpr (V::kLaplacian) visc_heat -= VH[k];
      }
    }
    if (conduction)
      for (std::size_t k = 0; k < np; ++k) cond += CD[k];
    p.a[0][i] = ax;
    p.a[1][i] = ay;
    p.a[2][i] = az;
    vsig[i] = vs;
    if constexpr (Energy) (*dudt)[i] = E::rate(Ai, du, visc_heat, cond);
    // drho/dt = (1/Omega) sum_b m_b v_ab . grad W_ab(h_a), and h = eta (m/rho)^(1/d) gives
    // dh/dt = -h/(d rho) drho/dt (seed 000 eqs. 3.3.2, 3.5.1)
    if (hrate) hrate[i] = -hi / (d * rhoi) * (du / (*omega)[i]);
    if constexpr (Cont) {
      cont->store(i, rhoi, hi, drho, diff, count);
      sum_nb += count;
    }
  }
  }
  if constexpr (Cont) ContinuityOutput::finish(c, sum_nb, n);
}

template <bool GradH, class V, class E, bool Cont, class Shape>
void dispatch_dim(StageContext& c, const Shape& s, Factors& f) {
  if (c.p.dim() == 3) standard_loop<GradH, V, E, Cont, true>(c, s, f);
  else standard_loop<GradH, V, E, Cont, false>(c, s, f);
}

template <bool GradH, class V, class Shape>
void dispatch_energy(StageContext& c, bool energy, bool cont, const Shape& s, Factors& f) {
  if (energy) dispatch_dim<GradH, V, terms::EnergyOn, false>(c, s, f);
  else if (cont && !GradH) dispatch_dim<GradH, V, terms::EnergyOff, true>(c, s, f);
  else dispatch_dim<GradH, V, terms::EnergyOff, false>(c, s, f);
}

template <bool GradH, class Shape>
void dispatch_visc(StageContext& c, bool energy, bool cont, const Shape& s, Factors& f) {
  terms::with_viscosity(c.prm.physics, [&](auto tag) {
    dispatch_energy<GradH, typename decltype(tag)::type>(c, energy, cont, s, f);
  });
}

class ForcesStandard final : public Stage {
 public:
  explicit ForcesStandard(const Physics& ph)
      : grad_h_(ph.density == DensityMode::Summation || ph.density == DensityMode::Volume),
        energy_(ph.energy == Toggle::On), cont_(fuses_continuity(ph)),
        hrate_(ph.density == DensityMode::Summation && ph.smoothing == HMode::Variable) {}
  std::string_view name() const override { return "forces: standard"; }
  FieldSet needs() const override {
    FieldSet f;
    f.add(Field::Mass).add(Field::Density).add(Field::H).add(Field::Pressure).add(Field::SoundSpeed);
    if (grad_h_) f.add(Field::Omega);
    return f;
  }
  FieldSet writes() const override {
    FieldSet f;
    f.add(Field::SignalSpeed);
    if (cont_) f.add(Field::DensityRate).add(Field::Neighbours);
    if (hrate_) f.add(Field::HRate);
    return f;
  }
  bool sets_acceleration() const override { return true; }
  bool run(StageContext& c) override {
    // the kernel shape is chosen once here, not per pair
    shape::with_shape(c.kernel.type(), c.p.dim(), [&](auto s) {
      if (grad_h_) dispatch_visc<true>(c, energy_, cont_, s, factors_);
      else dispatch_visc<false>(c, energy_, cont_, s, factors_);
    });
    return true;
  }
  double dt_limit(const StageContext& c) const override { return courant_limit(c.p); }

 private:
  bool grad_h_, energy_, cont_, hrate_;
  Factors factors_;
};

}  // namespace

std::unique_ptr<Stage> make_forces_standard(const Physics& ph) { return std::make_unique<ForcesStandard>(ph); }

}  // namespace sph
