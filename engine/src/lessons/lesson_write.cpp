// A lesson as JSON text (sph/lesson.h lesson_json): the shipped files' layout, a step's keys one per line
// and each value on its line; numbers in their shortest exact text, so parse_lesson reads the same lesson.
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "sph/lesson.h"
#include "sph/param_table.h"
#include "text/number_text.h"

namespace sph {
namespace {

std::string json_string(const std::string& s) { return nlohmann::json(s).dump(-1, ' ', false); }

/// A set's value as it was read: a number where its text is one, otherwise a string.
std::string value_json(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const bool is_number = !text.empty() && end == text.c_str() + text.size() && std::isfinite(v) && exact_text(v) == text;
  return is_number ? text : json_string(text);
}

std::string sets_json(const LessonSets& sets) {
  std::string s = "{";
  for (std::size_t i = 0; i < sets.size(); ++i)
    s += (i ? ", " : "") + json_string(sets[i].first) + ": " + value_json(sets[i].second);
  return s + "}";
}

/// {"a": 1, "b": "x"} from the parts given, in order.
std::string object(const std::vector<std::pair<std::string, std::string>>& parts) {
  std::string s = "{";
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + json_string(parts[i].first) + ": " + parts[i].second;
  return s + "}";
}

std::string view_json(const LessonView& v) {
  std::vector<std::pair<std::string, std::string>> p;
  if (!v.color_by.empty()) p.emplace_back("color_by", json_string(v.color_by));
  if (v.panels) {
    std::string list = "[";
    for (std::size_t i = 0; i < v.panels->size(); ++i) list += (i ? ", " : "") + json_string((*v.panels)[i]);
    p.emplace_back("panels", list + "]");
  }
  if (v.log >= 0) p.emplace_back("log", v.log ? "true" : "false");
  if (!v.profile_axis.empty()) p.emplace_back("profile_axis", json_string(v.profile_axis));
  if (v.range) p.emplace_back("range", "[" + lesson_number(v.range->first) + ", " + lesson_number(v.range->second) + "]");
  if (v.zoom)
    p.emplace_back("zoom", "[" + lesson_number((*v.zoom)[0]) + ", " + lesson_number((*v.zoom)[1]) + ", " +
                               lesson_number((*v.zoom)[2]) + "]");
  if (v.cut_axis >= 0) p.emplace_back("cut", json_string(std::string(1, "xyz"[v.cut_axis]) + "=" + lesson_number(v.cut_at)));
  if (v.residuals >= 0) p.emplace_back("residuals", v.residuals ? "true" : "false");
  return p.empty() ? std::string() : object(p);
}

std::string check_json(const LessonCheck& k) {
  static const char* kTypes[] = {"falls", "compare", "below", "above"};
  std::vector<std::pair<std::string, std::string>> p;
  p.emplace_back("type", json_string(kTypes[static_cast<int>(k.type)]));
  p.emplace_back("metric", json_string(k.metric));
  if (k.reduce != "end") p.emplace_back("reduce", json_string(k.reduce));
  if (k.until > 0.0) p.emplace_back("until", lesson_number(k.until));
  if (k.type == LessonCheck::Type::Falls) {
    p.emplace_back("key", json_string(k.key));
    std::string list = "[";
    for (std::size_t i = 0; i < k.values.size(); ++i) list += (i ? ", " : "") + lesson_number(k.values[i]);
    p.emplace_back("values", list + "]");
  }
  if (k.type == LessonCheck::Type::Compare) {
    p.emplace_back("a", sets_json(k.a));
    p.emplace_back("b", sets_json(k.b));
    p.emplace_back("smaller", json_string(std::string(1, k.smaller)));
  }
  if (k.type == LessonCheck::Type::Falls || k.type == LessonCheck::Type::Compare) p.emplace_back("factor", lesson_number(k.factor));
  else p.emplace_back("limit", lesson_number(k.limit));
  return object(p);
}

std::string step_json(const LessonStep& st) {
  std::vector<std::pair<std::string, std::string>> p;
  p.emplace_back("title", json_string(st.title));
  p.emplace_back("text", json_string(st.text));
  if (!st.predict.empty()) p.emplace_back("predict", object({{"question", json_string(st.predict)}, {"answer", json_string(st.answer)}}));
  p.emplace_back("scene", json_string(st.scene));
  if (!st.sets.empty()) p.emplace_back("set", sets_json(st.sets));
  if (!st.change.empty()) p.emplace_back("change", json_string(st.change));
  if (!st.look_at.empty()) p.emplace_back("look_at", json_string(st.look_at));
  if (st.pause_at > 0.0) p.emplace_back("pause_at", lesson_number(st.pause_at));
  if (!st.sweep_key.empty()) {
    std::string values;
    for (const std::string& v : st.sweep_values) {
      double x = 0.0;  // numbers as numbers, choices (M6) as strings
      values += (values.empty() ? "" : ", ") + (parse_number(v, x) ? lesson_number(x) : json_string(v));
    }
    p.emplace_back("sweep", object({{"key", json_string(st.sweep_key)}, {"values", "[" + values + "]"}}));
  }
  if (const std::string v = view_json(st.view); !v.empty()) p.emplace_back("view", v);
  p.emplace_back("check", check_json(st.check));
  std::string s = "    {\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    s += "      " + json_string(p[i].first) + ": " + p[i].second + (i + 1 < p.size() ? ",\n" : "\n");
  return s + "    }";
}

}  // namespace

std::string lesson_number(double v) { return exact_text(v); }

std::string lesson_json(const Lesson& lesson) {
  std::string s = "{\n  \"title\": " + json_string(lesson.title) + ",\n";
  if (!lesson.summary.empty()) s += "  \"summary\": " + json_string(lesson.summary) + ",\n";
  s += "  \"steps\": [\n";
  for (std::size_t i = 0; i < lesson.steps.size(); ++i)
    s += step_json(lesson.steps[i]) + (i + 1 < lesson.steps.size() ? ",\n" : "\n");
  return s + "  ]\n}\n";
}

}  // namespace sph
