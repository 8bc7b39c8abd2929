// A lesson written as JSON (sph/lesson.h lesson_json, the GUI's lesson editor) reads back as the same
// lesson: every shipped lesson, and a step with every optional part.
#include <gtest/gtest.h>

#include <filesystem>
#include <tuple>

#include "sph/lesson.h"

namespace sph {
namespace {

/// Every field of a step, as one tuple (the view's and the check's too).
auto fields(const LessonStep& s) {
  const LessonView& v = s.view;
  const LessonCheck& k = s.check;
  return std::tie(s.title, s.text, s.scene, s.sets, s.change, s.look_at, s.predict, s.answer, s.pause_at, s.sweep_key,
                  s.sweep_values, v.color_by,
                  v.panels, v.log, v.profile_axis, v.range, v.zoom, v.cut_axis, v.cut_at, v.residuals, k.type, k.metric, k.reduce,
                  k.until, k.key, k.values, k.a, k.b, k.smaller, k.factor, k.limit);
}

void expect_round_trip(const Lesson& l, const std::string& where) {
  const Lesson back = parse_lesson(lesson_json(l), l.file);
  EXPECT_EQ(back.title, l.title) << where;
  EXPECT_EQ(back.summary, l.summary) << where;
  ASSERT_EQ(back.steps.size(), l.steps.size()) << where;
  for (std::size_t i = 0; i < l.steps.size(); ++i)
    EXPECT_TRUE(fields(back.steps[i]) == fields(l.steps[i])) << where << " step " << i + 1;
  EXPECT_EQ(lesson_json(back), lesson_json(l)) << where;  // and the text is stable
}

TEST(LessonWrite, EveryShippedLessonReadsBackTheSame) {
  const std::filesystem::path dir = std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "lessons";
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    expect_round_trip(load_lesson(e.path().string()), e.path().filename().string());
    ++count;
  }
  EXPECT_GE(count, 12);
}

TEST(LessonWrite, AStepWithEveryPartReadsBackTheSame) {
  const Lesson l = parse_lesson(R"({"title": "T \"quoted\"", "summary": "a\nb", "steps": [
    {"title": "all", "text": "x", "predict": {"question": "q?", "answer": "a."}, "scene": "sod",
     "set": {"kernel.type": "M6", "visc.alpha": 0.1, "scene.n_left": 200, "physics.energy": "on"},
     "change": "c", "look_at": "k", "pause_at": 0.05,
     "view": {"color_by": "vx", "panels": ["rho", "v"], "log": false, "profile_axis": "x", "range": [0.1, 1.2],
              "zoom": [0.25, -0.5, 4], "cut": "z=0.5", "residuals": true},
     "check": {"type": "compare", "metric": "L1_v", "reduce": "max", "until": 0.15, "a": {"visc.alpha": 1},
               "b": {"visc.alpha": 0}, "smaller": "a", "factor": 3}},
    {"title": "falls", "text": "y", "scene": "sod", "sweep": {"key": "kernel.type", "values": ["M6", "wendland_c2"]},
     "check": {"type": "falls", "metric": "L1_rho", "key": "scene.n_left", "values": [100, 200], "factor": 1.5}}]})",
                                "l.json");
  expect_round_trip(l, "hand-made");
}

}  // namespace
}  // namespace sph
