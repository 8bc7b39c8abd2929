// The lesson panel's helpers: the shipped lessons are found, and a step loads on screen as its check's
// first run (a compare step: run A with the a sets and the A/B comparison with the b sets).
#include "lesson_ui.h"

#include <gtest/gtest.h>

#include "sph/lesson_check.h"

namespace sph::gui {
namespace {

TEST(LessonUi, FindsTheShippedLessons) {
  const auto files = lesson_files();
  ASSERT_GE(files.size(), 4u);
  EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
  for (const auto& f : files) EXPECT_NO_THROW(load_lesson(f)) << f;
}

TEST(LessonUi, StepConfigIsTheChecksFirstRun) {
  const Lesson l = parse_lesson(R"({"title": "T", "steps": [
    {"title": "a", "text": "x", "scene": "sod", "set": {"kernel.type": "M6"},
     "check": {"type": "compare", "metric": "L1_v", "a": {"visc.alpha": 1}, "b": {"visc.alpha": 0, "visc.beta": 0}, "smaller": "a"}},
    {"title": "b", "text": "y", "scene": "sod",
     "check": {"type": "falls", "metric": "L1_rho", "key": "scene.n_left", "values": [120, 240]}},
    {"title": "c", "text": "z", "scene": "sod", "check": {"type": "below", "metric": "L1_rho", "limit": 1}}]})",
                                "t.json");
  const RunConfig a = step_config(l.steps[0]);
  EXPECT_EQ(a.params.kernel.type, KernelType::M6);
  EXPECT_DOUBLE_EQ(a.params.visc.alpha, 1.0);
  EXPECT_EQ(step_compare(l.steps[0]), (std::vector<std::string>{"visc.alpha=0", "visc.beta=0"}));
  EXPECT_DOUBLE_EQ(step_config(l.steps[1]).values.at("n_left"), 120.0);
  EXPECT_TRUE(step_compare(l.steps[1]).empty());
  EXPECT_EQ(step_config(l.steps[2]).scene->name, "sod");
}

TEST(LessonUi, AStepPutsItsViewOnScreenAndLeavesTheRest) {
  render::ViewSettings view;
  view.color_by = "rho";
  view.panels = {"rho", "p"};
  view.cmap = "magma";
  LessonView step;
  step.color_by = "vx";
  step.panels = std::vector<std::string>{"v"};
  step.log = 1;
  step.profile_axis = "r";
  apply_step_view(step, view);
  EXPECT_EQ(view.color_by, "vx");
  EXPECT_EQ(view.panels, (std::vector<std::string>{"v"}));
  EXPECT_TRUE(view.log_scale);
  EXPECT_EQ(view.profile_axis, 3);  // r
  EXPECT_EQ(view.cmap, "magma");    // not the step's to change
  apply_step_view(LessonView{}, view);  // a step without a view changes nothing
  EXPECT_EQ(view.color_by, "vx");
  EXPECT_TRUE(view.log_scale);
  LessonView one;
  one.panels = std::vector<std::string>{};  // [] : one panel, the colour-by field
  one.log = 0;
  one.profile_axis = "off";
  apply_step_view(one, view);
  EXPECT_TRUE(view.panels.empty());
  EXPECT_FALSE(view.log_scale);
  EXPECT_EQ(view.profile_axis, -1);
}

TEST(LessonUi, AStepPutsItsRangeZoomCutawayAndErrorStrip) {
  render::ViewSettings view;
  LessonView step;
  step.range = std::make_pair(0.1, 1.2);
  step.zoom = std::array<double, 3>{0.25, -0.5, 4.0};
  step.cut_axis = 1;
  step.cut_at = -0.25;
  step.residuals = 1;
  apply_step_view(step, view);
  EXPECT_FALSE(view.auto_range);
  EXPECT_FLOAT_EQ(view.range_min, 0.1f);
  EXPECT_FLOAT_EQ(view.range_max, 1.2f);
  EXPECT_FALSE(view.camera2d.fit);
  EXPECT_FLOAT_EQ(view.camera2d.center_x, 0.25f);
  EXPECT_FLOAT_EQ(view.camera2d.center_y, -0.5f);
  EXPECT_FLOAT_EQ(view.camera2d.zoom, 4.f);
  EXPECT_EQ(view.cut_axis, 1);
  EXPECT_FLOAT_EQ(view.cut_at, -0.25f);
  EXPECT_TRUE(view.residuals);
  apply_step_view(LessonView{}, view);  // left open: as it was
  EXPECT_FALSE(view.auto_range);
  EXPECT_EQ(view.cut_axis, 1);
}

}  // namespace
}  // namespace sph::gui
