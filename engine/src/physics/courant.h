// The Courant limit of the force stages: min over the fluid of h / v_sig (seed 003 §3; Monaghan 1997),
// before the Courant factor. A minimum, so the same for any thread count.
#pragma once
#include <algorithm>
#include <span>

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

/// The same limit per fluid particle: dt[i] = min(dt[i], h_i / v_sig,i) (individual time steps).
inline void courant_limits(const Particles& p, std::span<double> dt) {
  const auto& h = p[Field::H];
  const auto& vs = p[Field::SignalSpeed];
#pragma omp parallel for if (p.size() >= kParallelMin)
  for (std::size_t i = 0; i < dt.size(); ++i)
    if (vs[i] > 0.0) dt[i] = std::min(dt[i], h[i] / vs[i]);
}

}  // namespace sph
