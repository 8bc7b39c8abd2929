// Lesson files parsed and validated (sph/lesson.h): fields, defaults, number formatting of sets, and a
// LessonError naming the file and the key for each kind of malformed input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sph/lesson.h"

namespace sph {
namespace {

const char* kStep = R"("title": "s", "text": "t", "scene": "sod")";

std::string lesson_with(const std::string& step_body) {
  return std::string(R"({"title": "L", "steps": [{)") + step_body + "}]}";
}

/// The message of the LessonError parsing `text` throws ("" if it parses).
std::string error_of(const std::string& text) {
  try {
    parse_lesson(text, "dir/bad.json");
  } catch (const LessonError& e) {
    return e.what();
  }
  return "";
}

TEST(LessonParse, ReadsEveryField) {
  const Lesson l = parse_lesson(R"({"title": "T", "summary": "S", "steps": [
    {"title": "a", "text": "x", "scene": "sod", "set": {"kernel.type": "M6", "scene.n_left": 100, "visc.alpha": 0.5},
     "change": "c", "look_at": "k",
     "check": {"type": "falls", "metric": "L1_rho", "until": 0.1, "key": "scene.n_left", "values": [50, 100], "factor": 1.5}},
    {"title": "b", "text": "y", "scene": "sod",
     "check": {"type": "compare", "metric": "L1_v", "reduce": "max", "a": {"visc.alpha": 1}, "b": {"visc.alpha": 0}, "smaller": "a"}},
    {"title": "c", "text": "z", "scene": "kepler", "check": {"type": "above", "metric": "dE", "reduce": "growth", "limit": 1.6}}]})",
                                "l.json");
  EXPECT_EQ(l.title, "T");
  EXPECT_EQ(l.summary, "S");
  ASSERT_EQ(l.steps.size(), 3u);
  const LessonStep& a = l.steps[0];
  EXPECT_EQ(a.scene, "sod");
  ASSERT_EQ(a.sets.size(), 3u);
  EXPECT_EQ(a.sets[0], (std::pair<std::string, std::string>{"kernel.type", "M6"}));
  EXPECT_EQ(a.sets[1].second, "100");
  EXPECT_EQ(a.sets[2].second, "0.5");
  EXPECT_EQ(a.change, "c");
  EXPECT_EQ(a.look_at, "k");
  EXPECT_EQ(a.check.type, LessonCheck::Type::Falls);
  EXPECT_EQ(a.check.reduce, "end");
  EXPECT_DOUBLE_EQ(a.check.until, 0.1);
  EXPECT_EQ(a.check.values, (std::vector<double>{50, 100}));
  EXPECT_DOUBLE_EQ(a.check.factor, 1.5);
  const LessonCheck& b = l.steps[1].check;
  EXPECT_EQ(b.type, LessonCheck::Type::Compare);
  EXPECT_EQ(b.reduce, "max");
  EXPECT_LT(b.until, 0.0);  // the scene's t_end
  EXPECT_EQ(b.smaller, 'a');
  EXPECT_DOUBLE_EQ(b.factor, 1.0);
  EXPECT_EQ(b.b.at(0).second, "0");
  EXPECT_EQ(l.steps[2].check.type, LessonCheck::Type::Above);
  EXPECT_DOUBLE_EQ(l.steps[2].check.limit, 1.6);
  EXPECT_NE(lesson_text(l).find("Step 3/3: c"), std::string::npos);
  EXPECT_EQ(claim_text(l.steps[0]), "L1_rho at t = 0.1 falls by at least 1.5x at each step of scene.n_left = 50 -> 100");
}

TEST(LessonParse, SceneFileBesideTheLesson) {
  const auto dir = std::filesystem::temp_directory_path() / "sph_lesson_parse_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "my_sod.json") << R"({"scene": "sod", "params": {"scene.n_left": 60}})";
  const std::string lesson = lesson_with(R"("title": "s", "text": "t", "scene": "my_sod.json",
      "check": {"type": "below", "metric": "L1_rho", "limit": 1})");
  std::ofstream(dir / "l.json") << lesson;
  const Lesson l = load_lesson((dir / "l.json").string());
  EXPECT_EQ(l.steps[0].scene, (dir / "my_sod.json").string());
  std::filesystem::remove_all(dir);
}

TEST(LessonParse, MalformedInputNamesFileAndKey) {
  const std::string below = R"("check": {"type": "below", "metric": "L1_rho", "limit": 1})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"title": "x", "steps": [)", "not valid JSON"},
      {R"([1, 2])", "must be a JSON object"},
      {R"({"steps": []})", ": title:"},
      {R"({"title": "x", "steps": []})", ": steps:"},
      {R"({"title": "x", "colour": 1, "steps": []})", ": colour: unknown key"},
      {lesson_with(std::string(kStep) + R"(, "colour": 2, )" + below), "steps[0].colour: unknown key"},
      {lesson_with(R"("title": "s", "scene": "sod", )" + below), "steps[0].text: missing"},
      {lesson_with(std::string(kStep)), "steps[0].check: missing"},
      {lesson_with(std::string(kStep) + R"(, "title2": 1, )" + below), "steps[0].title2"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "rises", "metric": "L1_rho"})"), "steps[0].check.type"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho"})"), "steps[0].check.limit: missing"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho", "limit": "1"})"), "check.limit: must be a finite number"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho", "limit": 1, "key": "k"})"), "check.key: not a key"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho", "limit": 1, "factor": 0.9})"), "check.factor"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho", "limit": 1, "until": -1})"), "check.until"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L1_rho", "limit": 1, "reduce": "mean"})"), "check.reduce"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "below", "metric": "L_42", "limit": 1})"), "check.metric: scene sod has no metric 'L_42'"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "falls", "metric": "L1_rho", "key": "scene.n_left", "values": [50]})"), "check.values"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "falls", "metric": "L1_rho", "key": "scene.zz", "values": [50, 100]})"), "check.values: "},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "compare", "metric": "L1_rho", "a": {}, "b": {}, "smaller": "c"})"), "check.smaller"},
      {lesson_with(std::string(kStep) + R"(, "check": {"type": "compare", "metric": "L1_rho", "a": {"visc.alpha": 99}, "b": {}, "smaller": "a"})"), "check.a: "},
      {lesson_with(std::string(kStep) + R"(, "set": {"kernel.type": "M9"}, )" + below), "steps[0].set: "},
      {lesson_with(std::string(kStep) + R"(, "set": {"kernel.type": [1]}, )" + below), "steps[0].set.kernel.type"},
      {lesson_with(R"("title": "s", "text": "t", "scene": "nowhere", )" + below), "nowhere"},
      {lesson_with(R"("title": "s", "text": "t", "scene": "elliptical_drop", "check": {"type": "below", "metric": "tv_vx", "limit": 1})"), "check.metric"},
  };
  for (const auto& [text, where] : cases) {
    const std::string msg = error_of(text);
    EXPECT_EQ(msg.rfind("dir/bad.json: ", 0), 0u) << text << " -> " << msg;
    EXPECT_NE(msg.find(where), std::string::npos) << text << " -> " << msg;
  }
}

TEST(LessonParse, AStepsViewIsRead) {
  const std::string below = R"("check": {"type": "below", "metric": "L1_rho", "limit": 1})";
  const Lesson l = parse_lesson(
      lesson_with(std::string(kStep) + R"(, "view": {"color_by": "vx", "panels": ["rho", "v"], "log": true, "profile_axis": "x"}, )" +
                  below),
      "l.json");
  const LessonView& v = l.steps[0].view;
  EXPECT_EQ(v.color_by, "vx");
  ASSERT_TRUE(v.panels.has_value());
  EXPECT_EQ(*v.panels, (std::vector<std::string>{"rho", "v"}));
  EXPECT_EQ(v.log, 1);
  EXPECT_EQ(v.profile_axis, "x");
  EXPECT_NE(lesson_text(l).find("view: colour by vx; panels rho, v; log10 scale; profile along x"), std::string::npos);
  const LessonView none = parse_lesson(lesson_with(std::string(kStep) + ", " + below), "l.json").steps[0].view;
  EXPECT_TRUE(none.color_by.empty());
  EXPECT_FALSE(none.panels.has_value());  // the viewer's panels stay
  EXPECT_EQ(none.log, -1);
  const LessonView one = parse_lesson(lesson_with(std::string(kStep) + R"(, "view": {"panels": []}, )" + below), "l.json")
                             .steps[0].view;
  ASSERT_TRUE(one.panels.has_value());  // [] : the colour-by field alone
  EXPECT_TRUE(one.panels->empty());
  for (const auto& [view, where] : std::vector<std::pair<std::string, std::string>>{
           {R"("view": 3)", "steps[0].view: must be an object"},
           {R"("view": {"colour": "vx"})", "steps[0].view.colour: unknown key"},
           {R"("view": {"panels": "rho"})", "steps[0].view.panels: must be a list"},
           {R"("view": {"log": 1})", "steps[0].view.log: must be true or false"},
           {R"("view": {"profile_axis": "z"})", "steps[0].view.profile_axis: 'z' is not one of off, x, y, r"}}) {
    const std::string msg = error_of(lesson_with(std::string(kStep) + ", " + view + ", " + below));
    EXPECT_NE(msg.find(where), std::string::npos) << view << " -> " << msg;
  }
}

TEST(LessonParse, ViewRangeZoomCutAndResidualsAQuestionAndAPause) {
  const std::string below = R"("check": {"type": "below", "metric": "L1_rho", "limit": 1})";
  const Lesson l = parse_lesson(
      lesson_with(std::string(kStep) +
                  R"(, "view": {"range": [0.1, 1.2], "zoom": [0.25, -0.5, 4], "cut": "z=0.5", "residuals": true},)"
                  R"( "predict": {"question": "Where is the error largest?", "answer": "At the contact."},)"
                  R"( "pause_at": 0.05, )" + below),
      "l.json");
  const LessonStep& st = l.steps[0];
  ASSERT_TRUE(st.view.range.has_value());
  EXPECT_EQ(*st.view.range, std::make_pair(0.1, 1.2));
  ASSERT_TRUE(st.view.zoom.has_value());
  EXPECT_EQ(*st.view.zoom, (std::array<double, 3>{0.25, -0.5, 4.0}));
  EXPECT_EQ(st.view.cut_axis, 2);
  EXPECT_EQ(st.view.cut_at, 0.5);
  EXPECT_EQ(st.view.residuals, 1);
  EXPECT_EQ(st.predict, "Where is the error largest?");
  EXPECT_EQ(st.answer, "At the contact.");
  EXPECT_EQ(st.pause_at, 0.05);
  const std::string text = lesson_text(l);
  EXPECT_NE(text.find("range 0.1 to 1.2; centre (0.25, -0.5), zoom 4; cutaway z <= 0.5; error strip"), std::string::npos);
  EXPECT_NE(text.find("predict first: Where is the error largest?\n  answer: At the contact."), std::string::npos);
  EXPECT_NE(text.find("pauses at t = 0.05"), std::string::npos);
  for (const auto& [part, where] : std::vector<std::pair<std::string, std::string>>{
           {R"("view": {"range": [1, 1]})", "steps[0].view.range: must be [min, max] with min < max"},
           {R"("view": {"range": [0, "1"]})", "steps[0].view.range: must be"},
           {R"("view": {"zoom": [0, 0, 0]})", "steps[0].view.zoom: must be [centre x, centre y, zoom] with zoom > 0"},
           {R"("view": {"zoom": [0, 0]})", "steps[0].view.zoom"},
           {R"("view": {"cut": "w=0"})", "steps[0].view.cut: 'w=0' is not AXIS=VALUE"},
           {R"("view": {"cut": "z=nan"})", "steps[0].view.cut"},
           {R"("view": {"residuals": "yes"})", "steps[0].view.residuals: must be true or false"},
           {R"("predict": "why?")", "steps[0].predict: must be an object"},
           {R"("predict": {"question": "why?"})", "steps[0].predict.answer: missing"},
           {R"("predict": {"question": "", "answer": "a"})", "steps[0].predict: question and answer must not be empty"},
           {R"("predict": {"question": "q", "answer": "a", "hint": "h"})", "steps[0].predict.hint: unknown key"},
           {R"("pause_at": 0)", "steps[0].pause_at: must be a time > 0"},
           {R"("pause_at": "soon")", "steps[0].pause_at: must be a finite number"}}) {
    const std::string msg = error_of(lesson_with(std::string(kStep) + ", " + part + ", " + below));
    EXPECT_NE(msg.find(where), std::string::npos) << part << " -> " << msg;
  }
}

TEST(LessonParse, ASweepOfOneKeyAndItsErrors) {
  const std::string below = R"("check": {"type": "below", "metric": "L1_rho", "limit": 1})";
  const Lesson l = parse_lesson(
      lesson_with(std::string(kStep) + R"(, "sweep": {"key": "kernel.eta", "values": [1.0, "1.5"]}, )" + below), "l.json");
  EXPECT_EQ(l.steps[0].sweep_key, "kernel.eta");
  EXPECT_EQ(l.steps[0].sweep_values, (std::vector<std::string>{"1", "1.5"}));
  EXPECT_NE(lesson_text(l).find("sweep: kernel.eta = 1, 1.5"), std::string::npos) << lesson_text(l);
  const std::string compare =
      R"("check": {"type": "compare", "metric": "L1_rho", "a": {"visc.alpha": 1}, "b": {"visc.alpha": 0}, "smaller": "a", "factor": 1.5})";
  for (const auto& [part, where] : std::vector<std::pair<std::string, std::string>>{
           {R"("sweep": [1, 2])", "steps[0].sweep: must be an object"},
           {R"("sweep": {"key": "kernel.eta", "values": []})", "steps[0].sweep.values: must be a list of 1 to 5 values"},
           {R"("sweep": {"key": "kernel.eta", "values": [1, 1.1, 1.2, 1.3, 1.4, 1.5]})", "steps[0].sweep.values: must be a list of 1 to 5"},
           {R"("sweep": {"key": "kernel.eta", "values": [true]})", "steps[0].sweep.values: must hold strings or numbers"},
           {R"("sweep": {"key": "kernel.eta", "values": [9]})", "steps[0].sweep: check kernel.eta: key 'kernel.eta': kernel.eta = 9 is out of range"},
           {R"("sweep": {"key": "kernel.etta", "values": [1]})", "steps[0].sweep: "},
           {R"("sweep": {"key": "kernel.eta", "values": [1], "colour": 1})", "steps[0].sweep.colour: unknown key"}}) {
    const std::string msg = error_of(lesson_with(std::string(kStep) + ", " + part + ", " + below));
    EXPECT_NE(msg.find(where), std::string::npos) << part << " -> " << msg;
  }
  const std::string msg = error_of(lesson_with(std::string(kStep) + R"(, "sweep": {"key": "kernel.eta", "values": [1]}, )" + compare));
  EXPECT_NE(msg.find("steps[0].sweep: a step with a compare check shows A and B, not a sweep"), std::string::npos) << msg;
}

TEST(LessonParse, UnreadableFile) {
  try {
    load_lesson("/nonexistent/l.json");
    FAIL() << "no error";
  } catch (const LessonError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/l.json"), std::string::npos);
  }
}

TEST(LessonParse, EveryShippedLessonParses) {
  const std::filesystem::path dir = std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "lessons";
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    EXPECT_NO_THROW(load_lesson(e.path().string())) << e.path();
    ++count;
  }
  EXPECT_GE(count, 4);
}

}  // namespace
}  // namespace sph
