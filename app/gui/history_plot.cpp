#include "history_plot.h"

namespace sph::gui {
namespace {

template <class Get>
std::vector<float> resample_by(const std::vector<HistorySample>& h, Get&& get, int n) {
  std::vector<float> out;
  if (h.empty() || n < 2) return out;
  out.resize(static_cast<std::size_t>(n));
  const double t0 = h.front().t, t1 = h.back().t;
  std::size_t j = 0;
  for (int i = 0; i < n; ++i) {
    const double t = t0 + (t1 - t0) * i / (n - 1);
    while (j + 1 < h.size() && h[j + 1].t < t) ++j;
    double v = get(h[j]);
    if (j + 1 < h.size() && h[j + 1].t > h[j].t) {
      const double a = (t - h[j].t) / (h[j + 1].t - h[j].t);
      v += (a < 0 ? 0 : a > 1 ? 1 : a) * (get(h[j + 1]) - get(h[j]));
    }
    out[static_cast<std::size_t>(i)] = static_cast<float>(v);
  }
  return out;
}

}  // namespace

std::vector<float> resample(const std::vector<HistorySample>& h, double HistorySample::*field, int n) {
  return resample_by(h, [field](const HistorySample& s) { return s.*field; }, n);
}

std::vector<float> resample_ref(const std::vector<HistorySample>& h, std::size_t k, int n) {
  return resample_by(h, [k](const HistorySample& s) { return k < s.ref.size() ? s.ref[k] : 0.0; }, n);
}

}  // namespace sph::gui
