// The lesson editor (app/gui/lesson_editor.h): a step recorded from the run on screen loads that run
// again (its scene and changed parameters), carries the view, and a saved lesson reads back and passes
// `sph lesson check`'s parser; a lesson whose claim names a metric the scene lacks is not written.
#include "lesson_editor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "lesson_ui.h"
#include "sph/lesson_check.h"

namespace sph::gui {
namespace {

TEST(LessonEditor, ChangedSetsAreWhatDiffersFromTheScenesDefaults) {
  RunConfig cfg = RunConfig::from_scene("sod");
  EXPECT_TRUE(changed_sets(cfg).empty());
  cfg.set("physics.viscosity", "laplacian", "test");
  cfg.set("visc.nu", "0.01", "test");
  cfg.set("kernel.type", "M6", "test");
  cfg.set("scene.n_left", "200", "test");
  const LessonSets sets = changed_sets(cfg);
  ASSERT_FALSE(sets.empty());
  EXPECT_EQ(sets.front(), (std::pair<std::string, std::string>{"physics.viscosity", "laplacian"}));  // slots first
  for (const auto& kv : {std::pair<std::string, std::string>{"visc.nu", "0.01"}, {"kernel.type", "M6"}, {"scene.n_left", "200"}})
    EXPECT_NE(std::find(sets.begin(), sets.end(), kv), sets.end()) << kv.first;
  // the step's run is the run on screen: the same resolved parameters
  LessonStep st;
  st.scene = "sod";
  st.sets = sets;
  EXPECT_EQ(lesson_config(st, {}).to_json(), cfg.to_json());
}

TEST(LessonEditor, ARecordedStepCarriesTheViewAndAClaimAtTheRunsTime) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("kernel.type", "M6", "test");
  render::ViewSettings v;
  v.color_by = "vx";
  v.panels = {"rho", "v"};
  v.auto_range = false;
  v.range_min = -0.1f;
  v.range_max = 1.f;
  v.residuals = true;
  StepDraft d{"M6 on Sod", "The sextic spline.", "Smaller error?", "Yes, by 6%.", false, "L1_rho", 0.0035};
  const LessonStep st = record_step(cfg, v, 0.15, d);
  EXPECT_EQ(st.scene, "sod");
  EXPECT_EQ(st.check.until, 0.15);
  EXPECT_EQ(st.check.type, LessonCheck::Type::Below);
  EXPECT_EQ(st.view.color_by, "vx");
  EXPECT_EQ(st.view.residuals, 1);
  ASSERT_TRUE(st.view.range.has_value());
  EXPECT_EQ(st.view.range->first, double(-0.1f));
  render::ViewSettings back;  // the step puts the same view on screen again
  apply_step_view(st.view, back);
  EXPECT_EQ(back.color_by, v.color_by);
  EXPECT_EQ(back.panels, v.panels);
  EXPECT_EQ(back.range_min, v.range_min);
  EXPECT_TRUE(back.residuals);
}

TEST(LessonEditor, ASavedLessonReadsBackAndABadClaimIsNotWritten) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("lesson_editor_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  Lesson l;
  l.title = "Recorded";
  StepDraft d{"one", "text", "", "", false, "L1_rho", 0.01};
  l.steps.push_back(record_step(RunConfig::from_scene("sod"), render::ViewSettings{}, 0.1, d));
  const std::string path = (dir / "recorded.json").string();
  EXPECT_EQ(save_lesson(l, path), "");
  const Lesson back = load_lesson(path);
  ASSERT_EQ(back.steps.size(), 1u);
  EXPECT_EQ(back.steps[0].check.metric, "L1_rho");
  EXPECT_EQ(back.steps[0].check.until, 0.1);
  l.steps[0].check.metric = "no_such_metric";
  const std::string bad = (dir / "bad.json").string();
  EXPECT_NE(save_lesson(l, bad).find("no_such_metric"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(bad));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sph::gui
