// Small helpers shared by the integrators: y = x + c z over the phase-space arrays.
#pragma once
#include <vector>

#include "core/parallel.h"
#include "sph/integrator.h"

namespace sph::detail {

/// Copy of the evolved arrays.
struct Saved {
  std::array<std::vector<double>, 3> x, v;
  std::vector<std::vector<double>> y;  ///< one per PhaseSpace::evolved entry
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
  out.y.resize(s.evolved.size());
  for (std::size_t e = 0; e < s.evolved.size(); ++e) copy(out.y[e], *s.evolved[e].y, s.n);
}

/// dst[i] = base[i] + c * rate[i] for i < n.
inline void axpy(std::vector<double>& dst, const std::vector<double>& base, double c, const std::vector<double>& rate,
                 std::size_t n) {
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) dst[i] = base[i] + c * rate[i];
}

/// dst[i] = base[i] + c * (v[i] + drift[i]): a drift with the XSPH velocity.
inline void axpy2(std::vector<double>& dst, const std::vector<double>& base, double c, const std::vector<double>& v,
                  const std::vector<double>& drift, std::size_t n) {
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) dst[i] = base[i] + c * (v[i] + drift[i]);
}

/// x = base + c dx/dt with dx/dt = v (+ drift when the phase space has one), for axis k.
inline void drift(const PhaseSpace& s, int k, std::vector<double>& dst, const std::vector<double>& base, double c,
                  const std::vector<double>& v) {
  if (s.drifts()) axpy2(dst, base, c, v, *s.drift[k], s.n);
  else axpy(dst, base, c, v, s.n);
}

}  // namespace sph::detail
