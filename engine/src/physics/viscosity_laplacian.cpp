// Physical viscosity nu with the Laplacian written in first kernel derivatives (seed 004; Morris, Fox &
// Zhu 1997) in the standard loops, or through the velocity gradient and stress (seed 001 eqs. 51-52) in
// the corrected formulation. Explicit diffusion limit dt <= h^2 / (8 nu) (Morris et al. 1997, eq. 11).
#include <algorithm>

#include "core/parallel.h"
#include "core/stages.h"

namespace sph {
namespace {

class ViscosityLaplacian final : public Stage {
 public:
  ViscosityLaplacian() : Stage({.name = "viscosity: Laplacian", .needs = {Field::Density, Field::H}}) {}
  bool reads_every_list() const override { return false; }  // reads no lists
  double dt_limit(const StageContext& c) const override {
    const double nu = c.prm.visc.nu;
    if (!(nu > 0.0)) return kNoLimit;
    const std::size_t n = c.p.fluid();
    const auto& h = c.p[Field::H];
    double hmin = kNoLimit;
#pragma omp parallel for reduction(min : hmin) if (c.p.size() >= kParallelMin)
    for (std::size_t i = 0; i < n; ++i) hmin = std::min(hmin, h[i]);
    return 0.125 * hmin * hmin / nu;
  }
};

}  // namespace

std::unique_ptr<Stage> make_viscosity_laplacian() { return std::make_unique<ViscosityLaplacian>(); }

}  // namespace sph
