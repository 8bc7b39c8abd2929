// Dummy wall particles (Adami, Hu & Adams 2012, JCP 231, 7057, eq. 27): fixed wall particles in several
// layers take part in every sum; their pressure is extrapolated from the fluid around them,
//   P_w = [sum_f P_f W_wf + g . sum_f rho_f (x_w - x_f) W_wf] / sum_f W_wf      (static walls, a_w = 0),
// which carries the fluid pressure and its hydrostatic part across the wall, and their density follows
// from the Tait EOS inverted at P_w. P_w is not allowed below the background pressure liquid.p0: a
// negative wall pressure would glue the fluid to the wall.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "sph/eos.h"

namespace sph {
namespace {

class WallsDummy final : public Stage {
 public:
  WallsDummy()
      : Stage({.name = "walls: dummy particles",
               .needs = {Field::Mass, Field::H},
               .writes = {Field::Pressure, Field::Density, Field::SoundSpeed},
               .shares = {Field::Pressure, Field::Density, Field::SoundSpeed}}) {}
  bool run(StageContext& c) override {
    const Kernel& K = c.kernel;
    Particles& p = c.p;
    const std::size_t begin = p.fluid(), end = p.size();
    auto& P = p[Field::Pressure];
    auto& rho = p[Field::Density];
    auto& cs = p[Field::SoundSpeed];
    const auto& h = p[Field::H];
    const LiquidParams& l = c.prm.liquid;
    const bool body = c.prm.physics.body_force == BodyForce::Uniform;
    const double g[3] = {body ? c.prm.body.gx : 0.0, body ? c.prm.body.gy : 0.0, body ? c.prm.body.gz : 0.0};
    const double support = K.support();
#pragma omp parallel for schedule(dynamic, 64) if (end >= kParallelMin)  // the scene's size decides
    for (std::size_t w = begin; w < end; ++w) {
      const double hw = h[w], R2 = support * support * hw * hw;
      double num = 0.0, den = 0.0;
      for (std::uint32_t f : c.nl.of(w)) {
        if (p.kind[f]) continue;
        double r[3];
        for (int k = 0; k < 3; ++k) r[k] = p.x[k][w] - p.x[k][f];
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (r2 >= R2) continue;
        const double W = K.W(std::sqrt(r2), hw);
        num += (P[f] + rho[f] * (g[0] * r[0] + g[1] * r[1] + g[2] * r[2])) * W;
        den += W;
      }
      P[w] = den > 0.0 ? std::max(l.p0, num / den) : l.p0;
      rho[w] = eos::tait_density(P[w], l);
      cs[w] = eos::tait_sound_speed(rho[w], l);
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<Stage> make_walls_dummy() { return std::make_unique<WallsDummy>(); }

}  // namespace sph
