// Small helpers shared by the integrators: y = x + c z over the phase-space arrays.
#pragma once
#include <vector>
#include "core/parallel.h"

#include "sph/integrator.h"

namespace sph::detail {

/// Copy of the evolved arrays.
struct Saved {
  std::array<std::vector<double>, 3> x, v;
  std::vector<double> u;
};

/// dst[0..n) = src[0..n) (threaded for large n).
inline void copy(std::vector<double>& dst, const std::vector<double>& src, std::size_t n) {
  dst.resize(n);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) dst[i] = src[i];
}

inline void save(const PhaseSpace& s, Saved& out) {
  for (int k = 0; k < s.dim; ++k) {
    copy(out.x[k], *s.x[k], s.n);
    copy(out.v[k], *s.v[k], s.n);
  }
  if (s.u) copy(out.u, *s.u, s.n);
}

/// dst[i] = base[i] + c * rate[i] for i < n.
inline void axpy(std::vector<double>& dst, const std::vector<double>& base, double c, const std::vector<double>& rate,
                 std::size_t n) {
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) dst[i] = base[i] + c * rate[i];
}

}  // namespace sph::detail
