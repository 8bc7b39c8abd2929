// The viscosity switch stage (visc.switch = balsara | cullen_dehnen): before the force loop, it measures
// div v and |curl v| of every fluid particle by kernel sums and writes its alpha (Field::ViscAlpha),
// which the force loops read through terms/visc_monaghan_switched.h:
//   div v_a  = -1/(Omega_a rho_a) sum_b m_b v_ab . grad W_ab(h_a)
//   curl v_a =  1/(Omega_a rho_a) sum_b m_b v_ab x grad W_ab(h_a)        (Omega = 1 without grad-h terms)
// Balsara: alpha_a = visc.alpha f_a; Cullen-Dehnen: alpha_a from its law (terms/visc_switch_law.h), which
// remembers the last evaluation's div v (Field::DivV) and starts every particle at alpha_min: a shock
// present at the start raises it from the second evaluation on (with alpha_min = 0, Sod's L1(rho) is
// 3% higher starting at alpha_min than at alpha_max; on the Gresho vortex alpha_max would damp the first
// 0.2 time units: L1(v_phi) 0.062 against 0.056 with Wendland C4, eta = 2, 64^2). Wall
// particles keep the reference alpha (visc.alpha or alpha_max). The stage runs once per evaluation (the
// density stage, which may ask for a rerun, comes before it).
#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "core/stages.h"
#include "pair_block.h"
#include "terms/visc_monaghan_switched.h"
#include "terms/visc_switch_law.h"

namespace sph {
namespace {

/// Reads the kernel sums' fields (Omega with grad-h terms); writes div v, |curl v| and alpha, and
/// shares alpha (the force loop reads it of the neighbours).
StageContract contract(ViscSwitch s, bool grad_h) {
  StageContract c{.name = s == ViscSwitch::Balsara ? "viscosity switch: Balsara" : "viscosity switch: Cullen-Dehnen",
                  .needs = {Field::Mass, Field::Density, Field::H, Field::SoundSpeed},
                  .writes = {Field::DivV, Field::CurlV, Field::ViscAlpha},
                  .shares = {Field::ViscAlpha}};
  if (grad_h) c.needs.add(Field::Omega);
  return c;
}

class ViscositySwitch final : public Stage {
 public:
  explicit ViscositySwitch(ViscSwitch s, bool grad_h) : Stage(contract(s, grad_h)), switch_(s), grad_h_(grad_h) {}

  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const double* m = p[Field::Mass].data();
    const double* rho = p[Field::Density].data();
    const double* h = p[Field::H].data();
    const double* cs = p[Field::SoundSpeed].data();
    const double* omega = grad_h_ ? p[Field::Omega].data() : nullptr;
    double* divv = p[Field::DivV].data();
    double* curl = p[Field::CurlV].data();
    double* alpha = p[Field::ViscAlpha].data();
    const Params& prm = c.prm;
    const double ref = terms::ViscMonaghanSwitched::reference(prm);
    const terms::CullenDehnenLaw law{prm.visc.alpha_min, prm.visc.alpha_max, prm.visc.decay};
    const bool first = !started_;
    const bool skip_walls = !c.walls_in_sums();
    const Kernel& K = c.kernel;
    const double support = K.support();
    const double dt = c.since;
#pragma omp parallel if (p.size() >= kParallelMin)
    {
      PairBlock<0> b;
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        const double hi = h[i];
        const std::size_t np = gather_within(p, i, c.nl.of(i), support * support * hi * hi, skip_walls, b);
        const Kernel::Scale si = K.scale(hi);
        double div = 0.0, cx = 0.0, cy = 0.0, cz = 0.0;
        for (std::size_t k = 0; k < np; ++k) {
          const std::uint32_t j = b.j[k];
          const double r2 = b.r2[k];
          if (r2 == 0.0) continue;  // i itself
          const double r = std::sqrt(r2);
          double W, dW;
          K.eval(si, r, W, dW);
          const double g = m[j] * dW / r;  // m_b grad W = m_b (dW/dr / r) r_vec
          const double rx = b.dx[k], ry = b.dy[k], rz = b.dz[k];
          const double vx = p.v[0][i] - p.v[0][j], vy = p.v[1][i] - p.v[1][j], vz = p.v[2][i] - p.v[2][j];
          div -= g * (vx * rx + vy * ry + vz * rz);
          cx += g * (vy * rz - vz * ry);
          cy += g * (vz * rx - vx * rz);
          cz += g * (vx * ry - vy * rx);
        }
        const double norm = 1.0 / ((omega ? omega[i] : 1.0) * rho[i]);
        const double dv = div * norm;
        const double cv = std::sqrt(cx * cx + cy * cy + cz * cz) * norm;
        if (switch_ == ViscSwitch::Balsara) {
          alpha[i] = ref * terms::balsara_factor(dv, cv, cs[i], hi);
        } else {
          alpha[i] = first ? prm.visc.alpha_min : law.next(alpha[i], dv, divv[i], cv, dt, cs[i], support * hi);
        }
        divv[i] = dv;
        curl[i] = cv;
      }
    }
    for (std::size_t i = n; i < p.size(); ++i) alpha[i] = ref;  // walls
    started_ = true;
    return true;
  }

  // Whether alpha has been started: a checkpoint resumes the run bit for bit.
  std::vector<std::vector<double>> saved_state() const override { return {{started_ ? 1.0 : 0.0}}; }
  bool restore_state(const std::vector<std::vector<double>>& s) override {
    if (s.size() != 1 || s[0].size() != 1) return false;
    started_ = s[0][0] != 0.0;
    return true;
  }

 private:
  ViscSwitch switch_;
  bool grad_h_;
  bool started_ = false;
};

}  // namespace

std::unique_ptr<Stage> make_viscosity_switch(const Physics& ph) {
  return std::make_unique<ViscositySwitch>(ph.visc_switch, ph.density == DensityMode::Summation ||
                                                               ph.density == DensityMode::Volume);
}

}  // namespace sph
