// A uniform body force g (gravity near the ground): dv/dt += g, potential energy -sum m g . x.
#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class BodyForceUniform final : public Stage {
 public:
  BodyForceUniform() : Stage({.name = "body force: uniform g", .needs = {Field::Mass}}) {}
  bool uses_neighbours() const override { return false; }
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const double g[3] = {c.prm.body.gx, c.prm.body.gy, c.prm.body.gz};
    for (int k = 0; k < p.dim(); ++k) {
      auto& a = p.a[k];
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
      for (std::size_t i = 0; i < n; ++i) a[i] += g[k];
    }
    return true;
  }
  double potential(const StageContext& c) const override {
    const Particles& p = c.p;
    const auto& m = p[Field::Mass];
    const double g[3] = {c.prm.body.gx, c.prm.body.gy, c.prm.body.gz};
    double e = 0.0;  // serial: the same for any thread count
    for (std::size_t i = 0; i < p.fluid(); ++i) {
      double gx = 0.0;
      for (int k = 0; k < p.dim(); ++k) gx += g[k] * p.x[k][i];
      e -= m[i] * gx;
    }
    return e;
  }
};

}  // namespace

std::unique_ptr<Stage> make_body_force_uniform() { return std::make_unique<BodyForceUniform>(); }

}  // namespace sph
