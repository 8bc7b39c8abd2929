// The parameter widgets driven through ImGui itself, without a window (app/gui/param_widgets.h):
// synthetic mouse and key input, frames built and thrown away. Typed values are taken as they are
// (Ctrl+click on the cfl slider and typing 0.3 gave cfl = 10^0.3 = 2; 0.5 gave "cfl = 3.16 is out of
// range"; visc.eps 0.1 became 1.26).
#include <gtest/gtest.h>

#include <imgui.h>

#include <string>

#include "imgui_context.h"
#include "param_widgets.h"

namespace sph::gui {
namespace {

constexpr int kEnter = 13, kKeyA = 'A';

class ParamWidget : public test::ImGuiTest {
 protected:
  void SetUp() override {
    start(900.f, 400.f);
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Enter] = kEnter;
    io.KeyMap[ImGuiKey_A] = kKeyA;
    p_.time.cfl = 0.25;
    p_.visc.eps = 0.01;
    frame();  // layout: where the slider and the field are
  }

  /// One frame with the widget of `key_`; records the slider's and the field's rectangles.
  void frame() {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0.f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(880.f, 380.f));
    ImGui::Begin("params", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::PushItemWidth(600.f);
    slider_ = ImGui::GetCursorScreenPos();
    param_widget(*find_param(key_), p_, false, &err_);
    field_min_ = ImGui::GetItemRectMin();
    field_max_ = ImGui::GetItemRectMax();
    ImGui::PopItemWidth();
    ImGui::End();
    ImGui::Render();
  }
  void frames(int n) {
    for (int k = 0; k < n; ++k) frame();
  }
  void click(ImVec2 at, bool ctrl) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = at;
    io.KeyCtrl = ctrl;
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
    io.KeyCtrl = false;
    io.MousePos = ImVec2(-100.f, -100.f);
    frame();
  }
  void press(int key, bool ctrl = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeysDown[key] = true;
    frame();
    io.KeysDown[key] = false;
    io.KeyCtrl = false;
    frame();
  }
  void type(const char* text) {
    press(kKeyA, true);  // select what the field shows
    ImGui::GetIO().AddInputCharactersUTF8(text);
    frame();
    press(kEnter);
    frames(2);
  }
  ImVec2 slider_centre() const { return ImVec2(slider_.x + 100.f, slider_.y + 0.5f * (field_max_.y - field_min_.y)); }
  ImVec2 field_centre() const { return ImVec2(0.5f * (field_min_.x + field_max_.x), 0.5f * (field_min_.y + field_max_.y)); }

  std::string key_ = "time.cfl";
  Params p_;
  std::string err_;
  ImVec2 slider_, field_min_, field_max_;
};

TEST_F(ParamWidget, CtrlClickOnTheLogSliderDoesNotReadTheTextAsLog10) {
  click(slider_centre(), true);
  type("0.3");
  EXPECT_LT(p_.time.cfl, 1.0) << "0.3 was taken as log10(cfl)";
  EXPECT_TRUE(err_.empty()) << err_;
}

TEST_F(ParamWidget, TypedValuesAreTakenAsTheyAre) {
  ASSERT_GT(field_min_.x, slider_.x + 200.f);  // the field is beside the slider
  for (const char* text : {"0.3", "0.5", "2"}) {
    click(field_centre(), false);
    type(text);
    EXPECT_EQ(p_.time.cfl, std::stod(text)) << text;
    EXPECT_TRUE(err_.empty()) << err_;
  }
  click(field_centre(), false);
  type("3");  // out of range: refused with the typed value in the message, cfl unchanged
  EXPECT_EQ(p_.time.cfl, 2.0);
  EXPECT_NE(err_.find("cfl = 3 is out of range"), std::string::npos) << err_;
}

TEST_F(ParamWidget, ViscEpsTakesTheTypedTenth) {
  key_ = "visc.eps";
  frame();
  click(field_centre(), false);
  type("0.1");
  EXPECT_EQ(p_.visc.eps, 0.1);
}

TEST_F(ParamWidget, DraggingToTheRightEndGivesTheRangeEnd) {
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = slider_centre();
  frame();
  io.MouseDown[0] = true;
  frame();
  for (float x = slider_centre().x; x < 1200.f; x += 100.f) {
    io.MousePos.x = x;
    frame();
  }
  io.MouseDown[0] = false;
  frames(2);
  EXPECT_EQ(p_.time.cfl, 2.0);
  EXPECT_TRUE(err_.empty()) << err_;
}

TEST(ZeroText, ASliderAtZeroSaysWhatZeroMeans) {
  EXPECT_EQ(zero_text(*find_param("kernel.eta")), "0 (the kernel's default)");  // it showed a bare 0
  EXPECT_EQ(zero_text(*find_param("density.diffusion")), "0 (off)");
  EXPECT_EQ(zero_text(*find_param("visc.alpha")), "");  // 0 is just no viscosity
}

}  // namespace
}  // namespace sph::gui
