// A Dear ImGui context without a window for the GUI's unit tests: frames are built and thrown away.
#pragma once
#include <gtest/gtest.h>
#include <imgui.h>

namespace sph::gui::test {

/// Creates the context (no ini file, 60 frames/s, the font atlas built) for a display of w x h px.
class ImGuiTest : public ::testing::Test {
 protected:
  void start(float w, float h) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(w, h);
    io.DeltaTime = 1.f / 60.f;
    unsigned char* pixels = nullptr;
    int aw = 0, ah = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &aw, &ah);
  }
  void TearDown() override { ImGui::DestroyContext(); }
};

}  // namespace sph::gui::test
