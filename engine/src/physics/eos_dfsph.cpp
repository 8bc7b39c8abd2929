// The incompressible liquid (physics.eos = dfsph): no equation of state. In an evaluation the stage sets
// P = 0 and c = 0, so the force stage sums only the other forces (viscosity; the body force adds g);
// the world then steps by project(): the divergence-free solve on v, v += dt a, the constant-density
// solve, and x += dt v (Bender & Koschier 2017, Algorithm 1, symplectic Euler; dfsph_solver.h). The
// time step is a CFL on the fastest particle, dt = cfl h / |v|_max (theirs: 0.4 d / |v|_max, d the
// particle diameter; h = 1.3 dx and cfl 0.3 give 0.39 dx / |v|_max), not a sound speed.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"
#include "physics/dfsph_solver.h"

namespace sph {
namespace {

class EosDfsph final : public Stage {
 public:
  EosDfsph()
      : Stage({.name = "pressure: DFSPH",
               .needs = {Field::Mass, Field::Density, Field::H},
               .writes = {Field::Pressure, Field::SoundSpeed, Field::DfsphKappa, Field::DfsphKappaV},
               .shares = {Field::Pressure, Field::SoundSpeed}}) {}
  bool run(StageContext& c) override {
    Particles& p = c.p;
    std::fill(p[Field::Pressure].begin(), p[Field::Pressure].begin() + static_cast<std::ptrdiff_t>(p.size()), 0.0);
    std::fill(p[Field::SoundSpeed].begin(), p[Field::SoundSpeed].begin() + static_cast<std::ptrdiff_t>(p.size()), 0.0);
    return true;
  }
  bool projects() const override { return true; }
  void project(StageContext& c, double dt) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    ProjectionStats& st = c.stats.projection;
    solver_.prepare(c);
    st.divergence_iterations = solver_.divergence(c, dt);
    for (int k = 0; k < p.dim(); ++k)
      for (std::size_t a = 0; a < n; ++a) p.v[k][a] += dt * p.a[k][a];  // the other forces
    st.density_iterations = solver_.density(c, dt, st);
    solver_.finish(c, dt);
  }
  double dt_limit(const StageContext& c) const override {
    const Particles& p = c.p;
    const auto& h = p[Field::H];
    double dt = kNoLimit;
    for (std::size_t a = 0; a < p.fluid(); ++a) {
      const double v = p.vel(a).norm();
      if (v > 0.0) dt = std::min(dt, h[a] / v);
    }
    return dt;
  }

 private:
  DfsphSolver solver_;
};

}  // namespace

std::unique_ptr<Stage> make_eos_dfsph() { return std::make_unique<EosDfsph>(); }

}  // namespace sph
