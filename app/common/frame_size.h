// "1280x720" -> width 1280, height 720: the --size / --record-size syntax of both programs.
#pragma once
#include <charconv>
#include <string>

namespace sph::render {

/// False if malformed (signs, spaces, trailing text), out of int range or not positive.
inline bool parse_frame_size(const std::string& text, int* w, int* h) {
  const char* end = text.data() + text.size();
  int width = 0, height = 0;
  const auto [x, e1] = std::from_chars(text.data(), end, width);
  if (e1 != std::errc() || x == end || *x != 'x') return false;
  const auto [stop, e2] = std::from_chars(x + 1, end, height);
  if (e2 != std::errc() || stop != end || width <= 0 || height <= 0) return false;
  *w = width;
  *h = height;
  return true;
}

}  // namespace sph::render
