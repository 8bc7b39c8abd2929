// Frames of a parameter sweep (FrameScene::sweep, profile_view.cpp): in 1D every run's dots in its own
// colour at its own values, one legend row per run with its L1, no colour bar; a grid of panels with the
// runs named once above them; a sweep run's dot picked as that run; without an exact curve the strip
// under the profile shows each run minus run A.
#include <gtest/gtest.h>

#include "frame_scene.h"
#include "profile_residual.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class RenderSweep : public OffscreenTest {};

/// sod_profile_1d with its density scaled by `f` on (0, 0.15), where the exact curve is flat.
Snapshot scaled_run(int n, float f) {
  Snapshot s = sod_profile_1d(n);
  for (std::size_t i = 0; i < s.count; ++i)
    if (s.x[i] > 0.f && s.x[i] < 0.15f) s.fields.front().values[i] *= f;
  return s;
}

FrameScene sweep_of(const Snapshot& a, const Snapshot& b, const Snapshot& c) {
  FrameScene scene;
  scene.a = &a;
  scene.sweep_key = "kernel.eta";
  scene.label_a = "kernel.eta=1.2 (A)";
  scene.value_a = "1.2 (A)";
  scene.errors_a = {{"L1_rho", 0.003}};
  scene.sweep.push_back({&b, "kernel.eta=1", "1", {{"L1_rho", 0.0027}}});
  scene.sweep.push_back({&c, "kernel.eta=1.5", "1.5", {{"L1_rho", 0.0036}}});
  return scene;
}

TEST_F(RenderSweep, EveryRunInItsColourWithItsL1) {
  const Snapshot a = sod_profile_1d(400), b = scaled_run(400, 0.8f), c = scaled_run(400, 0.6f);
  const FrameScene scene = sweep_of(a, b, c);
  const auto rgba = render(scene, ViewSettings{});
  ASSERT_EQ(layout().legend_rows.size(), 4u);
  EXPECT_EQ(layout().legend_rows[0], "exact");
  EXPECT_EQ(layout().legend_rows[1], "kernel.eta=1.2 (A)   L1_rho = 0.003");
  EXPECT_EQ(layout().legend_rows[2], "kernel.eta=1   L1_rho = 0.0027");
  EXPECT_EQ(layout().legend_rows[3], "kernel.eta=1.5   L1_rho = 0.0036");
  EXPECT_EQ(layout().colorbar.w, 0.f);  // run colours, no colour map
  const Snapshot* runs[3] = {&a, &b, &c};
  int checked = 0, found[3] = {0, 0, 0};
  for (std::size_t i = 0; i < a.count; i += 3) {
    if (!(a.x[i] > 0.02f && a.x[i] < 0.13f)) continue;
    for (int r = 0; r < 3; ++r) {
      float px, py;
      ASSERT_TRUE(layout().to_pixel(runs[r]->x[i], runs[r]->fields[0].values[i], 0.f, &px, &py));
      found[r] += colour_near(rgba, kWidth, kHeight, px, py, to_pixel8(kRunColors[r]), r == 0 ? 3 : 1, 20);
    }
    ++checked;
  }
  EXPECT_GT(checked, 10);
  for (int r = 0; r < 3; ++r) EXPECT_EQ(found[r], checked) << "run " << r;
  // a dot of the sweep's second run is picked as that run
  std::size_t k = 0;
  while (k < c.count && !(c.x[k] > 0.05f)) ++k;
  ASSERT_LT(k, c.count);
  float px, py;
  ASSERT_TRUE(layout().to_pixel(c.x[k], c.fields[0].values[k], 0.f, &px, &py));
  const auto picked = renderer_->renderer().pick(px, py, 2.f);
  ASSERT_TRUE(picked.has_value());
  EXPECT_EQ(picked->run, kFirstSweepRun + 1);
}

TEST_F(RenderSweep, PanelsNameTheRunsOnceAndTheirLegendsByValue) {
  const Snapshot a = sod_profile_1d(400), b = scaled_run(400, 0.8f), c = scaled_run(400, 0.6f);
  ViewSettings v;
  v.panels = {"rho", "p"};
  render(sweep_of(a, b, c), v);
  // rho: exact + 3 runs; p: the synthetic snapshot's p has no exact curve, so its 3 runs alone
  ASSERT_GE(layout().legend_rows.size(), 4u);
  EXPECT_EQ(layout().legend_rows[1], "1.2 (A)   L1_rho = 0.003");
  EXPECT_EQ(layout().legend_rows[3], "1.5   L1_rho = 0.0036");
}

TEST(ProfileResidualSweep, EachRunMinusRunAWithoutAnExactCurve) {
  const Snapshot a = sod_profile_1d(400), b = scaled_run(400, 0.8f), c = scaled_run(400, 0.6f);
  ProfilePanel p;
  const Snapshot* snaps[3] = {&a, &b, &c};
  for (int r = 0; r < 3; ++r) {
    ProfileRun run;
    run.snap = snaps[r];
    run.run = r == 0 ? 0 : kFirstSweepRun + r - 1;
    run.solid = kRunColors[r];
    run.y.assign(snaps[r]->fields.front().values.begin(), snaps[r]->fields.front().values.end());
    p.runs.push_back(run);
  }
  p.versus_first = "run - A";
  ASSERT_TRUE(has_residuals(p));
  const ProfilePanel r = residual_panel(p, 0);
  EXPECT_EQ(r.y_title.rfind("run - A", 0), 0u);
  ASSERT_EQ(r.runs.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(r.runs[static_cast<std::size_t>(k)].solid.r, kRunColors[k + 1].r);
    const float scale = k == 0 ? 0.8f : 0.6f;
    for (std::size_t i = 0; i < a.count; ++i) {
      if (a.x[i] > 0.005f && a.x[i] < 0.145f) {  // run minus A at A's x: (scale - 1) rho_A
        EXPECT_NEAR(r.runs[static_cast<std::size_t>(k)].y[i], (scale - 1.f) * a.fields[0].values[i], 1e-6f) << i;
      }
    }
  }
}

}  // namespace
}  // namespace sph::render::test
