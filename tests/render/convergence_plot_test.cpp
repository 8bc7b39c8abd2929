// The convergence study's plot (app/headless/convergence_plot.h, converge.png): the runs, the fitted line
// and order-1 and order-2 guides through the coarsest run, each in the legend; no colour bar; the chart
// fills the frame; its x axis names the step dx, not h (the smoothing length).
#include "convergence_plot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render_test_util.h"

namespace sph::render::test {
namespace {

ConvergenceResult first_order_study() {
  ConvergenceResult r;
  r.scene = "burgers_upwind";
  r.key = "scene.n";
  r.column = "e_seed";
  r.t = 0.8;
  for (double dx : {0.04, 0.02, 0.01}) {
    ConvergenceRun run;
    run.h = dx;
    run.error = 0.5 * dx;  // order 1
    r.runs.push_back(run);
  }
  r.slope = 1.0;
  return r;
}

class ConvergencePlot : public OffscreenTest {};

TEST_F(ConvergencePlot, GuidesAndRunsInTheLegendAndNoColourBar) {
  const Snapshot s = cli::convergence_plot(first_order_study());
  EXPECT_EQ(s.x_label, "log10 dx (the initial spacing)");
  const auto guide = std::find_if(s.outlines.begin(), s.outlines.end(), [](const Outline& o) { return o.label == "order 2"; });
  ASSERT_NE(guide, s.outlines.end());
  // through the coarsest run (log10 0.04, log10 0.02) with slope 2
  const float x = std::log10(0.04f), y = std::log10(0.02f);
  const float at = guide->y[0] + 2.f * (x - guide->x[0]);
  EXPECT_NEAR(at, y, 1e-5f);
  render(s, ViewSettings{});
  const auto& rows = layout().legend_rows;
  for (const char* want : {"least-squares fit, slope 1.00", "order 1", "order 2", "runs"})
    EXPECT_NE(std::find(rows.begin(), rows.end(), want), rows.end()) << want;
  EXPECT_EQ(layout().colorbar.w, 0.f);                 // it repeated the vertical axis
  EXPECT_GT(layout().plot.w, 1.5f * layout().plot.h);  // a chart fills the frame (a log-log strip before)
}

}  // namespace
}  // namespace sph::render::test
