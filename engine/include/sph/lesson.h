// Lessons: a JSON file (assets/lessons/) of steps, each with a short text, the scene and parameters to
// load, what to change, what to look at, and a claim the program checks by running the scene (see
// sph/lesson_check.h). Parsing validates everything a check needs (scene, keys, values, the metric) so a
// bad file is refused, naming the file and the key, before anything runs.
#pragma once
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sph {

/// A malformed lesson file: the message names the file and the key ("FILE: steps[2].check.factor: ...").
struct LessonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// key=value overrides in file order (values as text, as RunConfig::set takes them).
using LessonSets = std::vector<std::pair<std::string, std::string>>;

/// What a step claims. Every run starts from the step's scene and sets, runs to `until` and measures
/// `metric` (a reference column such as L1_rho or dE, or E_drift, tv_vx), reduced over the run by
/// `reduce`: "end" (the value at `until`), "max" (largest |value| after any step) or "growth" (largest
/// |value| in the second half of the run over the largest in the first half: 1 for a bounded error,
/// 2 for one growing linearly).
struct LessonCheck {
  enum class Type { Falls, Compare, Below, Above };
  Type type = Type::Below;
  std::string metric;
  std::string reduce = "end";
  double until = -1.0;  ///< < 0: the scene's time.t_end
  /// Falls: the metric at each value of `key` is below the previous one divided by `factor`.
  std::string key;
  std::vector<double> values;
  /// Compare: runs A and B (the step's sets, then these); the `smaller` run's metric times `factor` is
  /// below the other's.
  LessonSets a, b;
  char smaller = 'a';
  double factor = 1.0;  ///< Falls, Compare: the margin (>= 1)
  double limit = 0.0;   ///< Below, Above: the bound
};

/// What a step puts on screen, so that the view shows what its text talks about; each part optional
/// (empty, or -1: the viewer's choice stays).
struct LessonView {
  std::string color_by;             ///< a field of the step's scene (`sph help SCENE`: fields)
  /// Profile panels: field names, "v" (v_x in 1D, |v| otherwise); [] the colour-by field alone.
  std::optional<std::vector<std::string>> panels;
  int log = -1;                     ///< 0: linear colour scale, 1: log10
  std::string profile_axis;         ///< "off" (the plane), "x", "y", "r" (as --profile-axis)
  /// A fixed colour range (and profile y range) [min, max] in the field's units (log10 units with log).
  std::optional<std::pair<double, double>> range;
  /// The 2D plane view's centre (x, y) and zoom (1: the scene's bounds fill the plot, 2: twice as close).
  std::optional<std::array<double, 3>> zoom;
  /// 3D cutaway, read from "AXIS=VALUE" (as --cut, e.g. "z=0"): only particles with coordinate cut_axis
  /// (0, 1, 2 for x, y, z) <= cut_at are drawn, and the inside shows; cut_axis -1: the viewer's choice stays.
  int cut_axis = -1;
  double cut_at = 0.0;
  int residuals = -1;               ///< profiles: 1 the error strip under each panel, 0 none
};

struct LessonStep {
  std::string title, text;
  std::string scene;  ///< built-in name or scene file (relative to the lesson file's folder if it exists there)
  LessonSets sets;
  std::string change, look_at;
  LessonView view;
  LessonCheck check;
  /// A question to answer before running ("predict first") and its answer, which the GUI shows on a key.
  std::string predict, answer;
  double pause_at = -1.0;  ///< > 0: the GUI pauses the run when it reaches this time; Play goes on
  /// A parameter sweep the GUI runs beside the step's run ("sweep": {"key": K, "values": [...]}, at most
  /// 5 values), its runs drawn over each other in the profiles; no key: none.
  std::string sweep_key;
  std::vector<std::string> sweep_values;
};

struct Lesson {
  std::string file;  ///< where it was read from (messages)
  std::string title, summary;
  std::vector<LessonStep> steps;
};

/// Parses and validates lesson JSON text; `origin` names it in messages (and its folder resolves
/// relative scene files). Throws LessonError.
Lesson parse_lesson(const std::string& text, const std::string& origin);
/// Reads and parses a lesson file; throws LessonError (also when it cannot be read).
Lesson load_lesson(const std::string& path);
/// The lesson as JSON text in the shipped files' layout (a step's keys one per line); parse_lesson reads it
/// back to the same lesson. The GUI's lesson editor saves with it.
std::string lesson_json(const Lesson& lesson);
/// A number as lesson files and key=value overrides write it: the shortest text that reads back the same.
std::string lesson_number(double v);
/// The steps as text (`sph lesson show`): title, text, scene and sets, change, look at, the claim.
std::string lesson_text(const Lesson& lesson);
/// One line stating a step's claim, e.g. "L1_rho at t = 0.2 falls by 1.5x each time scene.n_left goes 100 -> 200 -> 400".
std::string claim_text(const LessonStep& step);
/// The measured quantity of a check as written in its results: "L1_rho", "max(dE)", "growth(dE)".
std::string metric_label(const LessonCheck& check);

}  // namespace sph
