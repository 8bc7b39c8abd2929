// `sph lesson show FILE` prints a lesson's steps; `sph lesson check FILE` runs every step's claim headless
// (exit 6: malformed lesson file, 7: a claim is false).
#pragma once
#include <string>

namespace sph::cli {

struct LessonOptions {
  std::string action;  ///< show or check
  std::string file;
  int threads = 0;
};

int lesson_command(const LessonOptions& opt);

}  // namespace sph::cli
