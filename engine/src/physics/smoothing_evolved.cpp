// Smoothing length evolved with the density: h_a = eta (m_a/rho_a)^(1/d) from the continuity density
// (seed 000 eq. 3.2.21 applied to the evolved rho; the same as integrating dh/dt = -h/(d rho) drho/dt
// exactly). Omega = 1: the continuity formulations have no grad-h terms.
#include <cmath>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class SmoothingEvolved final : public Stage {
 public:
  bool reads_every_list() const override { return false; }  // reads no lists
  explicit SmoothingEvolved(int dim)
      : Stage({.name = "smoothing length: evolved",
               .needs = {Field::Mass, Field::Density},
               .writes = {Field::H},
               .shares = {Field::H}}),
        dim_(dim) {}
  bool run(StageContext& c) override {
    Particles& p = c.p;
    const std::size_t n = p.fluid();
    const auto& m = p[Field::Mass];
    const auto& rho = p[Field::Density];
    auto& h = p[Field::H];
    const double inv_d = 1.0 / dim_, eta = c.eta;
    int outgrown = 0;
#pragma omp parallel for schedule(static) reduction(+ : outgrown) if (p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) {
      h[i] = eta * std::pow(m[i] / rho[i], inv_d);
      if (h[i] > c.h_limit[i]) ++outgrown;  // the list no longer covers h: rebuild it
    }
    return outgrown == 0;
  }

 private:
  int dim_;
};

}  // namespace

std::unique_ptr<Stage> make_smoothing_evolved(int dim) { return std::make_unique<SmoothingEvolved>(dim); }

}  // namespace sph
