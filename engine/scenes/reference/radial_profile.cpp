#include "reference/radial_profile.h"

#include <cmath>

namespace sph::scenes {

RadialProfile radial_profile(const Particles& p, Field f, double dr, std::size_t bins) {
  RadialProfile out;
  out.dr = dr;
  out.mean.assign(bins, 0.0);
  out.count.assign(bins, 0);
  const auto& v = p[f];
  for (std::size_t i = 0; i < p.fluid(); ++i) {
    const auto k = static_cast<std::size_t>(p.pos(i).norm() / dr);
    if (k >= bins) continue;
    out.mean[k] += v[i];
    ++out.count[k];
  }
  for (std::size_t k = 0; k < bins; ++k)
    if (out.count[k] > 0) out.mean[k] /= static_cast<double>(out.count[k]);
  return out;
}

Peak profile_peak(const RadialProfile& prof, std::size_t min_count) {
  Peak best;
  bool found = false;
  for (std::size_t k = 0; k < prof.mean.size(); ++k)
    if (prof.count[k] >= min_count && (!found || prof.mean[k] > best.value)) {
      best = {prof.mean[k], prof.centre(k)};
      found = true;
    }
  return best;
}

double shock_front(const RadialProfile& rho, double ahead) {
  const Peak peak = profile_peak(rho, 3);
  if (!(peak.value > ahead)) return 0.0;
  const double level = 0.5 * (peak.value + ahead);
  std::size_t k = static_cast<std::size_t>(peak.r / rho.dr);
  double r_prev = peak.r, v_prev = peak.value;
  for (++k; k < rho.mean.size(); ++k) {
    if (rho.count[k] == 0) continue;
    const double r = rho.centre(k), v = rho.mean[k];
    if (v < level) return r_prev + (v_prev - level) / (v_prev - v) * (r - r_prev);
    r_prev = r;
    v_prev = v;
  }
  return 0.0;
}

}  // namespace sph::scenes
