// Text layout checks on a rendered frame (the layout tests; app/gui/layout_check.h does the same for the
// GUI's own windows): a line of text running past the frame's edges is cut, and two lines whose boxes
// overlap (by more than a pixel each way) are drawn over each other.
#pragma once
#include <string>
#include <vector>

#include "text_batch.h"

namespace sph::render {

struct TextFault {
  std::string text, other;  ///< the line, and for an overlap the line it overlaps
  float x = 0.f, y = 0.f;   ///< where [px]
};

struct TextLayoutReport {
  int lines = 0;
  std::vector<TextFault> clipped, overlapping;
};

/// Checks the lines of a frame `width` x `height` px.
TextLayoutReport check_text(const std::vector<TextSpan>& spans, float width, float height);

/// "N lines, C cut at the frame's edge, O overlapping" and the first few faults, one per line.
std::string text_layout_text(const TextLayoutReport& r, std::size_t max_listed = 8);

}  // namespace sph::render
