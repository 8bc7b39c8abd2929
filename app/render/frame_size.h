// "1280x720" -> width 1280, height 720: the --size / --record-size syntax of both programs.
#pragma once
#include <cstdio>
#include <string>

namespace sph::render {

/// False if malformed (trailing text included) or not positive.
inline bool parse_frame_size(const std::string& text, int* w, int* h) {
  char x = 0, extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", w, &x, h, &extra) == 3 && x == 'x' && *w > 0 && *h > 0;
}

}  // namespace sph::render
