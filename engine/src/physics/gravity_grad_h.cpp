// The grad-h term of kernel-softened self-gravity (gravity.softening = kernel; Price & Monaghan 2007,
// MNRAS 374, 1347, eqs. 27-29). The potential energy E_pot = G/2 sum_a sum_b m_a m_b phi_ab depends on
// every h_a; with h_a = eta (m_a/rho_a)^(1/d) its rate of change is a force that the softened pair law
// alone leaves out, so energy leaks as h changes. Two stages after self-gravity add it:
//  - zeta: Z_a = zeta_a / Omega_a with zeta_a = (dh_a/drho_a) sum_b m_b dphi_ab(h_a)/dh_a,
//    dh/drho = -h/(d rho) [length^(d-1)]; b != a, as the pair sums of the potential;
//  - force: a_a += -(G/2) sum_b m_b (Z_a grad_a W_ab(h_a) + Z_b grad_a W_ab(h_b)) [length/time^2].
// dphi/dh is zero beyond the support, so both are sums over the SPH neighbours. The density stage's
// Omega and the summation density make dh_a/dt = (dh/drho) (1/Omega_a) sum_b m_b v_ab . grad W_ab(h_a)
// exact, so the force's work cancels dE_pot/dt through h to round-off.
#include <cmath>
#include <memory>
#include <optional>

#include "core/parallel.h"
#include "core/stages.h"
#include "gravity/softening.h"
#include "pair_block.h"

namespace sph {
namespace {

class GravityZeta final : public Stage {
 public:
  explicit GravityZeta(int dim)
      : Stage({.name = "gravity grad-h: zeta",
               .needs = {Field::Mass, Field::Density, Field::H, Field::Omega},
               .writes = {Field::GravZeta},
               .shares = {Field::GravZeta}}),
        dim_(dim) {}

  bool run(StageContext& c) override {
    Particles& p = c.p;
    if (!softening_ || type_ != c.prm.kernel.type) {
      softening_.emplace(c.prm.kernel.type);
      type_ = c.prm.kernel.type;
    }
    const gravity::KernelSoftening& law = *softening_;
    const std::size_t n = p.fluid();
    const double* m = p[Field::Mass].data();
    const double* rho = p[Field::Density].data();
    const double* h = p[Field::H].data();
    const double* omega = p[Field::Omega].data();
    double* Z = p[Field::GravZeta].data();
    const double support = law.support();
#pragma omp parallel if (p.size() >= kParallelMin)
    {
      PairBlock<0> b;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        const double hi = h[i];
        const std::size_t np = gather_within(p, i, c.nl.of(i), support * support * hi * hi, true, b);
        double sum = 0.0;  // sum_b m_b dphi/dh(r_ab, h_a), in list order
        for (std::size_t k = 0; k < np; ++k) {
          const std::uint32_t j = b.j[k];
          if (j == i || j >= n) continue;  // the gravity sources are the real particles, a != b
          sum += m[j] * law.dphi_dh(std::sqrt(b.r2[k]), hi);
        }
        Z[i] = -hi / (dim_ * rho[i]) * sum / omega[i];
      }
    }
    return true;
  }

 private:
  int dim_;
  std::optional<gravity::KernelSoftening> softening_;
  KernelType type_ = KernelType::M4;
};

class GravityGradH final : public Stage {
 public:
  GravityGradH()
      : Stage({.name = "gravity grad-h: force", .needs = {Field::Mass, Field::H, Field::GravZeta}, .writes = {}}) {}

  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const double* m = p[Field::Mass].data();
    const double* h = p[Field::H].data();
    const double* Z = p[Field::GravZeta].data();
    const Kernel& K = c.kernel;
    const double halfG = 0.5 * c.prm.gravity.G;
    support_radii2(p, K.support(), R2_);
#pragma omp parallel if (p.size() >= kParallelMin)
    {
      PairBlock<0> b;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t np = gather_pairs(p, R2_.data(), i, c.nl.of(i), true, b);
        const Kernel::Scale si = K.scale(h[i]);
        double ax = 0.0, ay = 0.0, az = 0.0;
        for (std::size_t k = 0; k < np; ++k) {
          const std::uint32_t j = b.j[k];
          if (j >= n) continue;
          const double r = std::sqrt(b.r2[k]);
          double W, dWi, dWj;
          K.eval(si, r, W, dWi);
          K.eval(K.scale(h[j]), r, W, dWj);
          // grad_a W_ab(h) = dW/dr (x_a - x_b) / r
          const double g = m[j] * (Z[i] * dWi + Z[j] * dWj) / r;
          ax += g * b.dx[k];
          ay += g * b.dy[k];
          az += g * b.dz[k];
        }
        p.a[0][i] -= halfG * ax;
        p.a[1][i] -= halfG * ay;
        p.a[2][i] -= halfG * az;
      }
    }
    return true;
  }

 private:
  std::vector<double> R2_;
};

}  // namespace

std::unique_ptr<Stage> make_gravity_zeta(int dim) { return std::make_unique<GravityZeta>(dim); }
std::unique_ptr<Stage> make_gravity_grad_h() { return std::make_unique<GravityGradH>(); }

}  // namespace sph
