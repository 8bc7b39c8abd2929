// Lesson JSON -> Lesson, every key checked (sph/lesson.h): unknown keys, wrong types and values, and each
// run's configuration (scene, keys, values, physics) and metric, so a bad file fails before any run.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lesson_json.h"
#include "lesson_metric.h"
#include "sph/compare.h"
#include "sph/lesson.h"
#include "sph/lesson_check.h"
#include "text/json_error_text.h"
#include "text/number_text.h"

namespace sph {
namespace {

using lessons::fail;
using lessons::json;
using lessons::number_of;
using lessons::only_keys;
using lessons::text_of;

/// {"kernel.type": "M6", "scene.n_left": 400} -> pairs (numbers written exactly, booleans as on/off).
LessonSets sets_of(const json& obj, const char* key, const std::string& origin, const std::string& path) {
  LessonSets out;
  if (!obj.contains(key)) return out;
  const json& s = obj[key];
  if (!s.is_object()) fail(origin, path + key, "must be an object of key: value");
  for (auto it = s.begin(); it != s.end(); ++it) {
    const json& v = it.value();
    std::string text;
    if (v.is_string()) text = v.get<std::string>();
    else if (v.is_number()) text = exact_text(v.get<double>());
    else if (v.is_boolean()) text = v.get<bool>() ? "on" : "off";
    else fail(origin, path + key + "." + it.key(), "must be a string or a number");
    out.emplace_back(it.key(), text);
  }
  return out;
}

LessonCheck check_of(const json& c, const std::string& origin, const std::string& path) {
  if (!c.is_object()) fail(origin, path, "must be an object");
  only_keys(c, {"type", "metric", "reduce", "until", "key", "values", "a", "b", "smaller", "factor", "limit"}, origin, path);
  const std::string p = path + ".";
  LessonCheck k;
  const std::string type = text_of(c, "type", true, origin, p);
  if (type == "falls") k.type = LessonCheck::Type::Falls;
  else if (type == "compare") k.type = LessonCheck::Type::Compare;
  else if (type == "below") k.type = LessonCheck::Type::Below;
  else if (type == "above") k.type = LessonCheck::Type::Above;
  else fail(origin, p + "type", "'" + type + "' is not a check type (falls, compare, below, above)");
  k.metric = text_of(c, "metric", true, origin, p);
  k.reduce = c.contains("reduce") ? text_of(c, "reduce", true, origin, p) : "end";
  if (k.reduce != "end" && k.reduce != "max" && k.reduce != "growth")
    fail(origin, p + "reduce", "'" + k.reduce + "' is not one of end, max, growth");
  k.until = number_of(c, "until", -1.0, origin, p);
  if (c.contains("until") && !(k.until > 0.0)) fail(origin, p + "until", "must be > 0");
  k.factor = number_of(c, "factor", 1.0, origin, p);
  if (!(k.factor >= 1.0)) fail(origin, p + "factor", "must be >= 1 (the margin of the claim)");
  const auto needs = [&](const char* key, bool wanted) {
    if (c.contains(key) != wanted)
      fail(origin, p + key, wanted ? "missing (check type " + type + " needs it)" : "not a key of check type " + type);
  };
  needs("key", k.type == LessonCheck::Type::Falls);
  needs("values", k.type == LessonCheck::Type::Falls);
  needs("a", k.type == LessonCheck::Type::Compare);
  needs("b", k.type == LessonCheck::Type::Compare);
  needs("smaller", k.type == LessonCheck::Type::Compare);
  needs("limit", k.type == LessonCheck::Type::Below || k.type == LessonCheck::Type::Above);
  if (k.type == LessonCheck::Type::Falls) {
    k.key = text_of(c, "key", true, origin, p);
    const json& v = c["values"];
    if (!v.is_array() || v.size() < 2) fail(origin, p + "values", "must be a list of at least two numbers");
    for (const json& x : v) {
      if (!x.is_number()) fail(origin, p + "values", "must be a list of numbers");
      k.values.push_back(x.get<double>());
    }
  }
  if (k.type == LessonCheck::Type::Compare) {
    k.a = sets_of(c, "a", origin, p);
    k.b = sets_of(c, "b", origin, p);
    const std::string s = text_of(c, "smaller", true, origin, p);
    if (s != "a" && s != "b") fail(origin, p + "smaller", "must be \"a\" or \"b\" (the run whose metric is the smaller)");
    k.smaller = s[0];
  }
  k.limit = number_of(c, "limit", 0.0, origin, p);
  return k;
}

/// "predict": {"question": "...", "answer": "..."}: both non-empty.
void predict_of(const json& s, LessonStep& st, const std::string& origin, const std::string& p) {
  if (!s.contains("predict")) return;
  const json& q = s["predict"];
  if (!q.is_object()) fail(origin, p + "predict", "must be an object {\"question\": ..., \"answer\": ...}");
  only_keys(q, {"question", "answer"}, origin, p + "predict");
  st.predict = text_of(q, "question", true, origin, p + "predict.");
  st.answer = text_of(q, "answer", true, origin, p + "predict.");
  if (st.predict.empty() || st.answer.empty()) fail(origin, p + "predict", "question and answer must not be empty");
}

/// "sweep": {"key": "kernel.eta", "values": [1.0, 1.5]}: 1 to 5 values, each a configuration the step's
/// scene accepts; not with a compare check (the GUI shows one or the other).
void sweep_of(const json& s, LessonStep& st, const std::string& origin, const std::string& p) {
  if (!s.contains("sweep")) return;
  const json& w = s["sweep"];
  if (!w.is_object()) fail(origin, p + "sweep", "must be an object {\"key\": ..., \"values\": [...]}");
  only_keys(w, {"key", "values"}, origin, p + "sweep");
  st.sweep_key = text_of(w, "key", true, origin, p + "sweep.");
  if (!w.contains("values") || !w["values"].is_array() || w["values"].empty() || w["values"].size() > kMaxSweepRuns)
    fail(origin, p + "sweep.values", "must be a list of 1 to " + std::to_string(kMaxSweepRuns) + " values");
  for (const json& v : w["values"]) {
    if (v.is_number()) st.sweep_values.push_back(exact_text(v.get<double>()));
    else if (v.is_string()) st.sweep_values.push_back(v.get<std::string>());
    else fail(origin, p + "sweep.values", "must hold strings or numbers");
    try {
      (void)lesson_config(st, {{st.sweep_key, st.sweep_values.back()}});
    } catch (const ConfigError& e) {
      fail(origin, p + "sweep", e.what());
    }
  }
  if (st.check.type == LessonCheck::Type::Compare) fail(origin, p + "sweep", "a step with a compare check shows A and B, not a sweep");
}

/// Every run the check makes can be configured and measures a metric its scene has.
void validate_runs(const LessonStep& st, const std::string& origin, const std::string& path) {
  std::vector<std::pair<LessonSets, std::string>> runs;  // extra sets, the key they come from
  const LessonCheck& k = st.check;
  if (k.type == LessonCheck::Type::Falls) {
    for (double v : k.values) runs.push_back({{{k.key, exact_text(v)}}, path + ".check.values"});
  } else if (k.type == LessonCheck::Type::Compare) {
    runs.push_back({k.a, path + ".check.a"});
    runs.push_back({k.b, path + ".check.b"});
  } else {
    runs.push_back({{}, path + ".set"});
  }
  for (const auto& [extra, where] : runs) {
    RunConfig cfg;
    try {
      cfg = lesson_config(st, extra);
    } catch (const ConfigError& e) {
      fail(origin, where, e.what());
    }
    bool known = false;
    const std::string names = lessons::metric_names(cfg, k.metric, &known);
    if (!known) fail(origin, path + ".check.metric", "scene " + cfg.scene->name + " has no metric '" + k.metric + "' (metrics:" + names + ")");
  }
}

}  // namespace

Lesson parse_lesson(const std::string& text, const std::string& origin) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw LessonError(origin + ": not valid JSON (" + json_error_text(e) + ")");
  }
  if (!doc.is_object()) throw LessonError(origin + ": the lesson must be a JSON object");
  only_keys(doc, {"title", "summary", "steps"}, origin, "");
  Lesson l;
  l.file = origin;
  l.title = text_of(doc, "title", true, origin, "");
  l.summary = text_of(doc, "summary", false, origin, "");
  if (!doc.contains("steps") || !doc["steps"].is_array() || doc["steps"].empty())
    fail(origin, "steps", "missing or not a non-empty list of steps");
  const std::filesystem::path folder = std::filesystem::path(origin).parent_path();
  for (std::size_t i = 0; i < doc["steps"].size(); ++i) {
    const json& s = doc["steps"][i];
    const std::string path = "steps[" + std::to_string(i) + "]";
    if (!s.is_object()) fail(origin, path, "must be an object");
    only_keys(s, {"title", "text", "scene", "set", "change", "look_at", "view", "check", "predict", "pause_at", "sweep"},
              origin, path);
    const std::string p = path + ".";
    LessonStep st;
    st.title = text_of(s, "title", true, origin, p);
    st.text = text_of(s, "text", true, origin, p);
    st.scene = text_of(s, "scene", true, origin, p);
    const std::filesystem::path local = folder / st.scene;
    std::error_code ec;  // a name the system refuses is not a local file
    if (st.scene.find('/') == std::string::npos && st.scene.size() > 5 &&
        st.scene.compare(st.scene.size() - 5, 5, ".json") == 0 && std::filesystem::exists(local, ec))
      st.scene = local.string();
    st.sets = sets_of(s, "set", origin, p);
    st.change = text_of(s, "change", false, origin, p);
    st.look_at = text_of(s, "look_at", false, origin, p);
    st.view = lessons::view_of(s, origin, p);
    predict_of(s, st, origin, p);
    st.pause_at = number_of(s, "pause_at", -1.0, origin, p);
    if (s.contains("pause_at") && !(st.pause_at > 0.0)) fail(origin, p + "pause_at", "must be a time > 0");
    if (!s.contains("check")) fail(origin, p + "check", "missing (every step makes a claim the program checks)");
    st.check = check_of(s["check"], origin, p + "check");
    validate_runs(st, origin, path);
    sweep_of(s, st, origin, p);
    l.steps.push_back(std::move(st));
  }
  return l;
}

Lesson load_lesson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw LessonError(path + ": cannot read the lesson file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_lesson(ss.str(), path);
}

}  // namespace sph
