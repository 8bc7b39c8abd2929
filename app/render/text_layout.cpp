// Text layout checks on a rendered frame (text_layout.h).
#include "text_layout.h"

#include <cstdio>

namespace sph::render {

TextLayoutReport check_text(const std::vector<TextSpan>& spans, float width, float height) {
  TextLayoutReport r;
  r.lines = static_cast<int>(spans.size());
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const TextSpan& a = spans[i];
    if (a.x0 < -0.5f || a.y0 < -0.5f || a.x1 > width + 0.5f || a.y1 > height + 0.5f) r.clipped.push_back({a.text, {}, a.x0, a.y0});
    for (std::size_t j = i + 1; j < spans.size(); ++j) {
      const TextSpan& b = spans[j];
      if (a.x0 + 1.f < b.x1 - 1.f && b.x0 + 1.f < a.x1 - 1.f && a.y0 + 1.f < b.y1 - 1.f && b.y0 + 1.f < a.y1 - 1.f)
        r.overlapping.push_back({a.text, b.text, a.x0, a.y0});
    }
  }
  return r;
}

std::string text_layout_text(const TextLayoutReport& r, std::size_t max_listed) {
  std::string s = std::to_string(r.lines) + " lines, " + std::to_string(r.clipped.size()) + " cut at the frame's edge, " +
                  std::to_string(r.overlapping.size()) + " overlapping";
  char at[48];
  for (std::size_t i = 0; i < r.clipped.size() && i < max_listed; ++i) {
    std::snprintf(at, sizeof at, " at (%.0f, %.0f)", r.clipped[i].x, r.clipped[i].y);
    s += std::string("\n  cut") + at + ": \"" + r.clipped[i].text + "\"";
  }
  for (std::size_t i = 0; i < r.overlapping.size() && i < max_listed; ++i) {
    std::snprintf(at, sizeof at, " at (%.0f, %.0f)", r.overlapping[i].x, r.overlapping[i].y);
    s += std::string("\n  overlap") + at + ": \"" + r.overlapping[i].text + "\" over \"" + r.overlapping[i].other + "\"";
  }
  return s;
}

}  // namespace sph::render
