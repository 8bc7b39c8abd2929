// The help window (app/gui/panel_help.cpp) driven through ImGui without a window: F1 (or H) opens it on
// the text `sph help SCENE` prints, with the values being edited; F1 again closes it.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <thread>

#include "gui_state.h"
#include "panels.h"
#include "imgui_context.h"
#include "sph/help_text.h"

namespace sph::gui {
namespace {

class PanelHelp : public test::ImGuiTest {
 protected:
  void SetUp() override { start(1200.f, 800.f); }

  void frame(GuiState& s, std::vector<int> keys) {
    s.key_presses = std::move(keys);
    ImGui::NewFrame();
    panel_help(s);
    ImGui::Render();
  }
};

TEST_F(PanelHelp, F1ShowsTheTextOfSphHelpForTheEditedScene) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "50", "test");
  Stepper stepper(cfg);
  GuiState s(stepper, cfg);
  for (int k = 0; k < 500 && !s.frame(); ++k) {  // the engine thread builds the World
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    s.update();
  }
  ASSERT_NE(s.frame(), nullptr);
  frame(s, {});
  EXPECT_FALSE(s.help.open);
  frame(s, {GLFW_KEY_F1});
  ASSERT_TRUE(s.help.open);
  EXPECT_EQ(s.help.text, scene_help(s.frame()->config));
  s.edit.visc.alpha = 0.5;  // an edit shows at once
  frame(s, {});
  EXPECT_NE(s.help.text.find("visc.alpha" + std::string(14, ' ') + " = 0.5" + std::string(11, ' ') +
                             "dimensionless, range [0, 10], default 1\n"),
            std::string::npos)
      << s.help.text;
  frame(s, {GLFW_KEY_H, GLFW_KEY_H});  // two taps between frames: open, closed, open again
  EXPECT_TRUE(s.help.open);
  frame(s, {GLFW_KEY_F1});
  EXPECT_FALSE(s.help.open);
}

}  // namespace
}  // namespace sph::gui
