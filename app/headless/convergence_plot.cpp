// The plot of a convergence study (convergence_plot.h).
#include "convergence_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace sph::cli {

Snapshot convergence_plot(const ConvergenceResult& r) {
  Snapshot s;
  s.scene = "converge";
  s.dim = 2;
  std::vector<float> xs, ys;  // log10 step, log10 error of the runs with a positive error
  for (const ConvergenceRun& run : r.runs)
    if (run.error > 0.0 && run.h > 0.0) {
      xs.push_back(static_cast<float>(std::log10(run.h)));
      ys.push_back(static_cast<float>(std::log10(run.error)));
    }
  float x0 = 0.f, x1 = 1.f, y0 = 0.f, y1 = 1.f;
  if (!xs.empty()) {
    x0 = *std::min_element(xs.begin(), xs.end());
    x1 = *std::max_element(xs.begin(), xs.end());
    y0 = *std::min_element(ys.begin(), ys.end());
    y1 = *std::max_element(ys.begin(), ys.end());
  }
  const float pad = 0.08f * std::max(0.3f, x1 - x0), lo = x0 - pad, hi = x1 + pad;
  // a line of the given slope through (ax, ay), across the plot; the vertical range takes it in over the
  // runs' own steps
  const auto line = [&](std::string label, float slope, float ax, float ay) {
    s.outlines.push_back({std::move(label), {lo, hi}, {ay + slope * (lo - ax), ay + slope * (hi - ax)}});
    for (float x : {x0, x1}) {
      y0 = std::min(y0, ay + slope * (x - ax));
      y1 = std::max(y1, ay + slope * (x - ax));
    }
  };
  if (!xs.empty()) {
    const std::size_t coarse = static_cast<std::size_t>(std::max_element(xs.begin(), xs.end()) - xs.begin());
    float mx = 0.f, my = 0.f;
    for (std::size_t k = 0; k < xs.size(); ++k) mx += xs[k], my += ys[k];
    mx /= static_cast<float>(xs.size());
    my /= static_cast<float>(xs.size());
    char fit[64];
    std::snprintf(fit, sizeof fit, "least-squares fit, slope %.2f", r.slope);
    line(fit, static_cast<float>(r.slope), mx, my);
    line("order 1", 1.f, xs[coarse], ys[coarse]);
    line("order 2", 2.f, xs[coarse], ys[coarse]);
    for (std::size_t k = 0; k < xs.size(); ++k) s.outlines.push_back({"runs", {xs[k]}, {ys[k]}});  // dots
  }
  const float vpad = 0.08f * std::max(0.3f, y1 - y0);
  s.bounds = {lo, hi, y0 - vpad, y1 + vpad, 0.f, 1.f};
  char title[256];
  std::snprintf(title, sizeof title, "convergence of %s: %s at t = %g against %s, fitted slope %.3f", r.scene.c_str(),
                r.column.c_str(), r.t, r.key.c_str(), r.slope);
  s.title = title;
  s.x_label = "log10 " + r.step_name() + " (" + r.step_meaning() + ")";  // not "h": the smoothing length
  s.y_label = "log10 " + r.column;
  return s;
}

}  // namespace sph::cli
