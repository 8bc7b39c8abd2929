#include "history_plot.h"

namespace sph::gui {

std::vector<float> resample(const std::vector<HistorySample>& h, double HistorySample::*field, int n) {
  std::vector<float> out;
  if (h.empty() || n < 2) return out;
  out.resize(static_cast<std::size_t>(n));
  const double t0 = h.front().t, t1 = h.back().t;
  std::size_t j = 0;
  for (int i = 0; i < n; ++i) {
    const double t = t0 + (t1 - t0) * i / (n - 1);
    while (j + 1 < h.size() && h[j + 1].t < t) ++j;
    double v = h[j].*field;
    if (j + 1 < h.size() && h[j + 1].t > h[j].t) {
      const double a = (t - h[j].t) / (h[j + 1].t - h[j].t);
      v += (a < 0 ? 0 : a > 1 ? 1 : a) * (h[j + 1].*field - h[j].*field);
    }
    out[static_cast<std::size_t>(i)] = static_cast<float>(v);
  }
  return out;
}

}  // namespace sph::gui
