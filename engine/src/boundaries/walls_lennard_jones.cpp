// Lennard-Jones wall particles (seed 001 eq. 60, §7.2; Monaghan 1994): each wall particle within r0 of
// a fluid particle pushes it away radially with D [(r0/r)^p1 - (r0/r)^p2] r/r^2 per unit mass. Wall
// particles take no part in the SPH sums. D = walls.D or the scene's (seed: D ~ 5 g H); r0 = walls.r0
// or the initial spacing. Conservative: its potential sum m phi(r) is part of E_pot.
#include "core/parallel.h"
#include "core/stages.h"
#include "sph/walls.h"

namespace sph {
namespace {

struct LjConstants {
  double D, r0, p1, p2;
};

LjConstants constants(const StageContext& c) {
  const WallParams& w = c.prm.walls;
  return {w.D > 0.0 ? w.D : c.wall_strength, w.r0 > 0.0 ? w.r0 : c.spacing, w.p1, w.p2};
}

class WallsLennardJones final : public Stage {
 public:
  WallsLennardJones() : Stage({.name = "walls: Lennard-Jones", .needs = {Field::Mass}}) {}
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const LjConstants lj = constants(c);
#pragma omp parallel for schedule(dynamic, 64) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      double f[3] = {0.0, 0.0, 0.0};
      for (std::uint32_t j : c.nl.of(i)) {
        if (!p.kind[j]) continue;
        double r[3];
        for (int k = 0; k < 3; ++k) r[k] = p.x[k][i] - p.x[k][j];
        const double rr = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        const double s = walls::lennard_jones_factor(rr, lj.D, lj.r0, lj.p1, lj.p2);
        for (int k = 0; k < 3; ++k) f[k] += s * r[k];
      }
      for (int k = 0; k < 3; ++k) p.a[k][i] += f[k];
    }
    return true;
  }
  double potential(const StageContext& c) const override {
    const Particles& p = c.p;
    const auto& m = p[Field::Mass];
    const LjConstants lj = constants(c);
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < p.fluid(); ++i)
      for (std::uint32_t j : c.nl.of(i)) {
        if (!p.kind[j]) continue;
        const double rr = (p.pos(i) - p.pos(j)).norm();
        e += m[i] * walls::lennard_jones_potential(rr, lj.D, lj.r0, lj.p1, lj.p2);
      }
    return e;
  }
};

}  // namespace

std::unique_ptr<Stage> make_walls_lennard_jones() { return std::make_unique<WallsLennardJones>(); }

}  // namespace sph
