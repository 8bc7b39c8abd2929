// A lesson's parameter settings (key=value pairs) as one line of text, for its description and results.
#pragma once
#include <string>

#include "sph/lesson.h"

namespace sph::lessons {

/// The pairs as key=value joined by `sep`; `none` when there are none (the scene's defaults).
inline std::string join_sets(const LessonSets& sets, const char* sep, const char* none) {
  std::string s;
  for (const auto& [k, v] : sets) s += (s.empty() ? "" : sep) + k + "=" + v;
  return s.empty() ? none : s;
}

}  // namespace sph::lessons
