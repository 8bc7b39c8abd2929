// Text layout checks on rendered frames (app/render/text_layout.h): a line past the frame's edge and two
// lines over each other are found; the title leaves out the particle count where it does not fit (it
// ran past the right edge at 3x text), so no line of a narrow frame is cut.
#include "text_layout.h"

#include <gtest/gtest.h>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

TEST(TextLayout, CutAndOverlappingLinesAreFound) {
  const std::vector<TextSpan> spans = {{"title", 10.f, 5.f, 200.f, 20.f},
                                       {"past the edge", 600.f, 5.f, 660.f, 20.f},
                                       {"tick 0.5", 10.f, 100.f, 60.f, 112.f},
                                       {"legend over it", 40.f, 104.f, 160.f, 116.f},
                                       {"beside, touching", 60.f, 100.f, 120.f, 112.f}};
  const TextLayoutReport r = check_text(spans, 640.f, 480.f);
  EXPECT_EQ(r.lines, 5);
  ASSERT_EQ(r.clipped.size(), 1u);
  EXPECT_EQ(r.clipped[0].text, "past the edge");
  ASSERT_EQ(r.overlapping.size(), 2u);  // the legend over the tick, and over the line beside the tick
  EXPECT_EQ(r.overlapping[0].text, "tick 0.5");
  EXPECT_EQ(r.overlapping[0].other, "legend over it");
  EXPECT_NE(text_layout_text(r).find("1 cut at the frame's edge, 2 overlapping"), std::string::npos);
}

class RenderTextLayout : public OffscreenTest {};

TEST_F(RenderTextLayout, ANarrowFrameAtLargeTextCutsNoLine) {
  const Snapshot s = sod_profile_1d(200);
  ViewSettings v;
  v.text_scale = 3;
  render(s, v, 640, 480);
  const TextLayoutReport r = check_text(renderer_->renderer().last_texts(), 640.f, 480.f);
  EXPECT_TRUE(r.clipped.empty()) << text_layout_text(r);
  EXPECT_TRUE(r.overlapping.empty()) << text_layout_text(r);
  bool title = false;
  for (const TextSpan& t : renderer_->renderer().last_texts()) title = title || t.text.rfind("sod", 0) == 0;
  EXPECT_TRUE(title);
}

}  // namespace
}  // namespace sph::render::test
