#include "ui_look.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace sph::gui {
namespace {

bool g_high_contrast = false;  // the look apply_ui_look applied last (plot_look); the GUI thread only

/// The dark theme with square corners (rounded ones cost a software rasteriser ~20% of the panels' time).
void base_style(bool high_contrast) {
  ImGuiStyle& s = ImGui::GetStyle();
  s = ImGuiStyle();
  ImGui::StyleColorsDark(&s);
  s.WindowRounding = s.ChildRounding = s.PopupRounding = s.FrameRounding = s.GrabRounding = 0.f;
  s.ScrollbarRounding = s.TabRounding = 0.f;
  s.WindowBorderSize = 1.f;
  s.ItemSpacing = ImVec2(8.f, 5.f);
  s.Colors[ImGuiCol_WindowBg] = ImVec4(0.09f, 0.09f, 0.10f, 1.f);
  if (!high_contrast) return;
  // white on black; frames, buttons and headers outlined; accents in yellow (21:1 text contrast)
  ImVec4* c = s.Colors;
  const ImVec4 black(0.f, 0.f, 0.f, 1.f), white(1.f, 1.f, 1.f, 1.f), yellow(1.f, 0.9f, 0.1f, 1.f);
  const ImVec4 blue(0.f, 0.2f, 0.55f, 1.f), bright_blue(0.1f, 0.35f, 0.85f, 1.f);
  c[ImGuiCol_Text] = white;
  c[ImGuiCol_TextDisabled] = ImVec4(0.85f, 0.85f, 0.85f, 1.f);
  c[ImGuiCol_WindowBg] = c[ImGuiCol_ChildBg] = c[ImGuiCol_PopupBg] = black;
  c[ImGuiCol_Border] = white;
  c[ImGuiCol_FrameBg] = ImVec4(0.12f, 0.12f, 0.12f, 1.f);
  c[ImGuiCol_FrameBgHovered] = c[ImGuiCol_FrameBgActive] = blue;
  c[ImGuiCol_TitleBg] = c[ImGuiCol_TitleBgActive] = c[ImGuiCol_TitleBgCollapsed] = ImVec4(0.15f, 0.15f, 0.15f, 1.f);
  c[ImGuiCol_Button] = c[ImGuiCol_Header] = blue;
  c[ImGuiCol_ButtonHovered] = c[ImGuiCol_HeaderHovered] = bright_blue;
  c[ImGuiCol_ButtonActive] = c[ImGuiCol_HeaderActive] = bright_blue;
  c[ImGuiCol_CheckMark] = c[ImGuiCol_SliderGrab] = c[ImGuiCol_SliderGrabActive] = yellow;
  c[ImGuiCol_PlotLines] = c[ImGuiCol_PlotHistogram] = yellow;
  c[ImGuiCol_Separator] = white;
  s.FrameBorderSize = 1.f;
}

}  // namespace

std::string ui_font_path() {
  const char* env = std::getenv("SPH_GUI_FONT");
  return env && *env ? env : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

std::string apply_ui_look(const UiLook& look, bool gl_ready, bool* fallback) {
  ImGuiIO& io = ImGui::GetIO();
  const float px = std::round(kUiFontPx * look.scale);
  io.Fonts->Clear();
  // Latin-1, Greek (alpha, beta, rho ...), the dash of an undefined value, arrows and the check marks of lessons
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2014, 0x2014, 0x2190, 0x2193,
                                   0x2212, 0x2212, 0x2713, 0x2717, 0};
  const std::string path = ui_font_path();
  std::error_code ec;
  ImFont* font = nullptr;
  if (std::filesystem::exists(path, ec)) font = io.Fonts->AddFontFromFileTTF(path.c_str(), px, nullptr, ranges);
  std::string what;
  *fallback = font == nullptr;
  if (font) {
    what = std::filesystem::path(path).filename().string() + " at " + std::to_string(static_cast<int>(px)) + " px";
  } else {
    ImFontConfig cfg;
    cfg.SizePixels = std::round(13.f * look.scale);  // ProggyClean is drawn for 13 px: blurry above that
    io.Fonts->AddFontDefault(&cfg);
    what = "font " + path + " not found: ImGui's built-in font at " + std::to_string(static_cast<int>(cfg.SizePixels)) +
           " px (install fonts-dejavu-core for crisp text)";
  }
  io.Fonts->Build();
  if (gl_ready) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  base_style(look.high_contrast);
  g_high_contrast = look.high_contrast;
  ImGui::GetStyle().ScaleAllSizes(look.scale);
  return what;
}

PlotLook plot_look() {
  if (g_high_contrast)
    return {IM_COL32(255, 255, 255, 255), IM_COL32(110, 110, 116, 255), IM_COL32(0, 0, 0, 255), IM_COL32(255, 255, 255, 255),
            IM_COL32(235, 235, 235, 255)};
  return {IM_COL32(150, 150, 160, 255), IM_COL32(70, 70, 78, 255), IM_COL32(36, 36, 42, 255), IM_COL32(225, 225, 230, 255),
          IM_COL32(160, 160, 170, 255)};
}

}  // namespace sph::gui
