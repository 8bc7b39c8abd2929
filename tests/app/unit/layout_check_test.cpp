// The text layout check on Dear ImGui's draw data (app/gui/layout_check.h), on frames built without a
// window: a label cut by its window's edge and text drawn over text are found, with their window and
// text; a tidy window has neither; a line cut at the bottom of a window with a scroll bar is not a fault; the
// frame where content first outgrows a window is not settled (its bar comes a frame later), the next one is.
#include "layout_check.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>

#include "imgui_context.h"

namespace sph::gui {
namespace {

class LayoutCheck : public test::ImGuiTest {
 protected:
  void SetUp() override { start(800.f, 600.f); }

  /// One frame with a 300 x 200 window "panel" whose content `body` draws, with a vertical scroll bar where
  /// its content is taller than it when `scroll_bar`; the check's report. The window is drawn `frames` times
  /// (ImGui decides on the scroll bar from the previous frame's content: after one, it has none yet).
  LayoutReport frame(const std::function<void()>& body, bool scroll_bar = false, int frames = 2) {
    for (int k = 0; k < frames; ++k) {
      ImGui::NewFrame();
      ImGui::SetNextWindowPos(ImVec2(10.f, 10.f));
      ImGui::SetNextWindowSize(ImVec2(300.f, 200.f));
      ImGui::Begin(scroll_bar ? "scrolling" : "panel", nullptr,
                   scroll_bar ? ImGuiWindowFlags_NoTitleBar : ImGuiWindowFlags_NoDecoration);
      body();
      ImGui::End();
      ImGui::Render();
    }
    return check_layout(*ImGui::GetDrawData(), *ImGui::GetIO().Fonts);
  }
};

TEST_F(LayoutCheck, ATidyWindowHasNoFault) {
  const LayoutReport r = frame([] {
    ImGui::TextUnformatted("physics.eos");
    ImGui::Button("Reset");
  });
  EXPECT_GT(r.glyphs, 12);
  EXPECT_TRUE(r.clipped.empty());
  EXPECT_TRUE(r.overlapping.empty());
}

TEST_F(LayoutCheck, ALabelCutByTheWindowsEdgeIsFound) {
  const LayoutReport r = frame([] { ImGui::TextUnformatted("a label much too long for a window only 300 pixels wide"); });
  ASSERT_FALSE(r.clipped.empty());
  EXPECT_EQ(r.clipped.front().window, "panel");
  EXPECT_NE(r.clipped.front().text.find("labelmuch"), std::string::npos);  // its line's glyphs (no spaces)
}

TEST_F(LayoutCheck, TextOverTextIsFound) {
  const LayoutReport r = frame([] {
    const ImVec2 at = ImGui::GetCursorPos();
    ImGui::TextUnformatted("E_kin 0.0722");
    ImGui::SetCursorPos(ImVec2(at.x + 20.f, at.y + 3.f));
    ImGui::TextUnformatted("0.053");
  });
  EXPECT_TRUE(r.clipped.empty());
  ASSERT_FALSE(r.overlapping.empty());
  EXPECT_NE(r.overlapping.front().text.find("over"), std::string::npos);
}

TEST_F(LayoutCheck, ALineCutAtTheBottomOfAScrollingWindowIsNotAFault) {
  const auto body = [] {
    for (int k = 0; k < 20; ++k) ImGui::Text("row %d", k);  // runs past the window's bottom
  };
  EXPECT_FALSE(frame(body).clipped.empty());       // a window without a scroll bar: cut
  EXPECT_TRUE(frame(body, true).clipped.empty());  // one with a scroll bar: scrolled out of view, not cut
}

TEST_F(LayoutCheck, AFrameIsSettledOnceItsWindowsHaveTheSizeOfTheirContent) {
  const auto body = [] {
    for (int k = 0; k < 20; ++k) ImGui::Text("row %d", k);
  };
  frame(body, true, 1);  // the content first appears: the window was laid out for none
  EXPECT_FALSE(layout_settled());
  frame(body, true, 1);  // the next frame: laid out for it
  EXPECT_TRUE(layout_settled());
}

}  // namespace
}  // namespace sph::gui
