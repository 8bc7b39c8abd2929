// Every shipped lesson step shows what its text talks about (sph/lesson.h, LessonView): a step whose
// "change" or "look_at" says "colour by X" colours by X, one that names "the X panel" shows that panel,
// and every field a step's view names is a field of the step's scene (artificial_viscosity's steps said
// "look at the v panel" and "colour by vx" while the view stayed on rho).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <cctype>
#include <string>
#include <vector>

#include "sph/lesson.h"
#include "sph/lesson_check.h"
#include "sph/world.h"

namespace sph {
namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The word after each "colour by " / "color by " in `text`.
std::vector<std::string> coloured_by(const std::string& text) {
  std::vector<std::string> out;
  for (const std::string key : {"colour by ", "color by "})
    for (std::size_t k = text.find(key); k != std::string::npos; k = text.find(key, k + 1)) {
      std::size_t e = k + key.size();
      while (e < text.size() && word_char(text[e])) ++e;
      out.push_back(text.substr(k + key.size(), e - k - key.size()));
    }
  return out;
}

/// The word before each " panel" in `text` ("the v panel" -> "v"); the GUI's own panels, named with a
/// capital ("the Sweep panel"), are not profile panels.
std::vector<std::string> panels_named(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t k = text.find(" panel"); k != std::string::npos; k = text.find(" panel", k + 1)) {
    std::size_t b = k;
    while (b > 0 && word_char(text[b - 1])) --b;
    if (b < k && !std::isupper(static_cast<unsigned char>(text[b]))) out.push_back(text.substr(b, k - b));
  }
  return out;
}

/// Whether `name` is a field of the snapshot or a panel alias ("v": v_x in 1D, |v| otherwise).
bool shows(const Snapshot& s, const std::string& name) { return name == "v" || s.find(name) != nullptr; }

TEST(LessonViews, EveryStepsViewMatchesItsTextAndItsScene) {
  const std::filesystem::path dir = std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "lessons";
  int steps = 0, views = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    const Lesson l = load_lesson(e.path().string());
    for (std::size_t i = 0; i < l.steps.size(); ++i) {
      const LessonStep& st = l.steps[i];
      const LessonView& v = st.view;
      const std::string where = e.path().filename().string() + " step " + std::to_string(i + 1);
      const std::string said = st.change + " " + st.look_at;
      ++steps;
      for (const std::string& field : coloured_by(said))
        EXPECT_EQ(v.color_by, field) << where << " says 'colour by " << field << "'";
      for (const std::string& p : panels_named(said)) {
        ASSERT_TRUE(v.panels.has_value()) << where << " says 'the " << p << " panel' and sets no panels";
        EXPECT_NE(std::find(v.panels->begin(), v.panels->end(), p), v.panels->end())
            << where << " says 'the " << p << " panel'";
      }
      if (v.color_by.empty() && !v.panels) continue;
      ++views;
      const Snapshot s = World(lesson_config(st, {})).report().snapshot();
      if (!v.color_by.empty()) {  // a field the GUI can colour by: the panels' "v" alias is not one
        EXPECT_NE(s.find(v.color_by), nullptr) << where << ": scene " << st.scene << " has no " << v.color_by;
      }
      for (const std::string& p : v.panels.value_or(std::vector<std::string>{})) {
        EXPECT_TRUE(shows(s, p)) << where << ": scene " << st.scene << " has no " << p;
      }
    }
  }
  std::printf("%d lesson steps, %d with a view\n", steps, views);
  EXPECT_GE(views, 7);
}

}  // namespace
}  // namespace sph
