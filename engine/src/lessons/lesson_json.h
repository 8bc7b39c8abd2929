// Reading a lesson's JSON (private to src/lessons): every failure a LessonError naming the file and the
// key's path, e.g. "FILE: steps[1].check.factor: must be >= 1".
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "sph/lesson.h"

namespace sph::lessons {

using json = nlohmann::json;

/// Throws a LessonError for `path` (e.g. "steps[1].check.factor") of the file `origin`.
[[noreturn]] inline void fail(const std::string& origin, const std::string& path, const std::string& what) {
  throw LessonError(origin + ": " + path + ": " + what);
}

/// Refuses keys of `obj` outside `allowed`.
inline void only_keys(const json& obj, const std::set<std::string>& allowed, const std::string& origin,
                      const std::string& path) {
  for (auto it = obj.begin(); it != obj.end(); ++it)
    if (!allowed.count(it.key())) {
      std::string list;
      for (const auto& k : allowed) list += " " + k;
      fail(origin, path + (path.empty() ? "" : ".") + it.key(), "unknown key (known:" + list + ")");
    }
}

inline std::string text_of(const json& obj, const char* key, bool required, const std::string& origin,
                           const std::string& path) {
  if (!obj.contains(key)) {
    if (required) fail(origin, path + key, "missing (a string)");
    return {};
  }
  if (!obj[key].is_string()) fail(origin, path + key, "must be a string");
  return obj[key].get<std::string>();
}

inline double number_of(const json& obj, const char* key, double fallback, const std::string& origin,
                        const std::string& path) {
  if (!obj.contains(key)) return fallback;
  if (!obj[key].is_number() || !std::isfinite(obj[key].get<double>())) fail(origin, path + key, "must be a finite number");
  return obj[key].get<double>();
}

/// A step's "view" (sph::LessonView), every key checked; `path` ends with "." ("steps[2].").
LessonView view_of(const json& step, const std::string& origin, const std::string& path);

}  // namespace sph::lessons
