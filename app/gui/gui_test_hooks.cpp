// The test hooks of sph-gui: scripted key taps, clicks, push drags and scrubbing, parsed from the options
// (checked by parse_options) at each displayed frame.
#include "gui_test_hooks.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cctype>
#include <cstdio>
#include <string>

#include "view_push.h"

namespace sph::gui {

void tap_keys_hook(const GuiOptions& o, long long frame, Window& window) {
  for (const std::string& t : o.tap_keys) {
    const auto colon = t.find(':');
    if (std::stoll(t.substr(0, colon)) != frame) continue;
    for (const char ch : t.substr(colon + 1)) {
      if (ch == '+' || ch == '-') window.tap_key(ch == '+' ? GLFW_KEY_EQUAL : GLFW_KEY_MINUS, GLFW_MOD_CONTROL);
      else if (ch == '!') window.tap_key(GLFW_KEY_S, GLFW_MOD_CONTROL);
      else window.tap_key(ch == ' ' ? GLFW_KEY_SPACE : std::toupper(ch));
    }
  }
}

void click_hook(const GuiOptions& o, long long frame, const ParticleView& view, const Rect& r) {
  for (const std::string& c : o.click_particles) {
    const auto colon = c.find(':');
    const long long at = std::stoll(c.substr(0, colon)), id = std::stoll(c.substr(colon + 1));
    if (frame != at && frame != at + 1) continue;
    if (const auto pos = view.window_pos_of(0, static_cast<std::uint32_t>(id), r)) {
      ImGuiIO& io = ImGui::GetIO();
      io.MousePos = ImVec2((*pos)[0], (*pos)[1]);
      io.MouseDown[0] = frame == at;
    }
  }
}

void push_drag_hook(const GuiOptions& o, long long frame, const ParticleView& view, const Rect& r) {
  for (const std::string& d : o.push_drags) {
    long long f0 = 0, f1 = 0;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    if (std::sscanf(d.c_str(), "%lld:%lld:%lf,%lf:%lf,%lf", &f0, &f1, &x0, &y0, &x1, &y1) != 6) continue;
    if (frame < f0 || frame > f1) continue;
    const double u = f1 > f0 ? static_cast<double>(frame - f0) / static_cast<double>(f1 - f0) : 1.0;
    float wx = 0, wy = 0;
    if (!window_pos_of_world(view, r, x0 + u * (x1 - x0), y0 + u * (y1 - y0), &wx, &wy)) continue;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(wx, wy);
    io.MouseDown[1] = frame < f1;
  }
}

void scrub_back_hook(const GuiOptions& o, const StepperFrame* f, GuiState& state) {
  if (o.scrub_back > 0 && f && f->at_end && !state.building() && state.scrub < 0 &&
      state.ring.size() > static_cast<std::size_t>(o.scrub_back))
    state.scrub = static_cast<int>(state.ring.size()) - 1 - o.scrub_back;
}

}  // namespace sph::gui
