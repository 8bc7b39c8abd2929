// The Courant limit of the force stages: min over the fluid of h / v_sig (seed 003 §3; Monaghan 1997),
// before the Courant factor. A minimum, so the same for any thread count.
#pragma once
#include <algorithm>

#include "core/parallel.h"
#include "core/stage.h"

namespace sph {

inline double courant_limit(const Particles& p) {
  const std::size_t n = p.fluid();
  const auto& h = p[Field::H];
  const auto& vs = p[Field::SignalSpeed];
  double dt = Stage::kNoLimit;
#pragma omp parallel for reduction(min : dt) if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i)
    if (vs[i] > 0.0) dt = std::min(dt, h[i] / vs[i]);
  return dt;
}

}  // namespace sph
