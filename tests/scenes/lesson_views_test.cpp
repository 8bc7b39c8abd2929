// Every shipped lesson step shows what its text talks about (sph/lesson.h, LessonView): a step whose
// "change" or "look_at" says "colour by X" colours by X, one that names "the X panel" shows that panel,
// and every field a step's view names is a field of the step's scene (artificial_viscosity's steps said
// "look at the v panel" and "colour by vx" while the view stayed on rho).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "sph/lesson.h"
#include "sph/lesson_check.h"
#include "sph/world.h"

namespace sph {
namespace {

/// Whether `name` is a field of the snapshot or a panel alias ("v": v_x in 1D, |v| otherwise).
bool shows(const Snapshot& s, const std::string& name) { return name == "v" || s.find(name) != nullptr; }

TEST(LessonViews, EveryStepsViewMatchesItsTextAndItsScene) {
  const std::filesystem::path dir = std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "lessons";
  const std::regex colour(R"(colou?r by ([A-Za-z_]+))"), panel(R"(\b([A-Za-z_]+) panel\b)");
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
      for (std::sregex_iterator m(said.begin(), said.end(), colour), end; m != end; ++m)
        EXPECT_EQ(v.color_by, (*m)[1].str()) << where << " says '" << (*m)[0] << "'";
      for (std::sregex_iterator m(said.begin(), said.end(), panel), end; m != end; ++m) {
        ASSERT_TRUE(v.panels.has_value()) << where << " says '" << (*m)[0] << "' and sets no panels";
        EXPECT_NE(std::find(v.panels->begin(), v.panels->end(), (*m)[1].str()), v.panels->end())
            << where << " says '" << (*m)[0] << "'";
      }
      if (v.color_by.empty() && !v.panels) continue;
      ++views;
      const Snapshot s = World(lesson_config(st, {})).report().snapshot();
      if (!v.color_by.empty()) {
        EXPECT_TRUE(shows(s, v.color_by)) << where << ": scene " << st.scene << " has no " << v.color_by;
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
