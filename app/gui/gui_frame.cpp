// The frame of sph-gui's main loop: keys and the UI look, the state's update, the panels and the view's
// mouse, the draw decision (idle frames keep the last picture), screenshots and the recording.
#include "gui_gl.h"  // first: GL prototypes before any other glcorearb.h include

#include "gui_frame.h"
#include "layout_check.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "draw_data_hash.h"
#include "gui_test_hooks.h"
#include "panels.h"
#include "png_writer.h"
#include "unique_path.h"
#include "view_picking.h"
#include "view_push.h"
#include "view_scene.h"

namespace sph::gui {
namespace {

Rect to_framebuffer(const Rect& r) {
  const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
  return {r.x * s.x, r.y * s.y, r.w * s.x, r.h * s.y};
}

bool screenshot(const std::string& path, int w, int h, std::string* err) {
  std::vector<std::uint8_t> rgba;
  read_window_rgba(w, h, &rgba);
  return write_png(path, w, h, rgba, err);
}

/// Starts or stops recording as the panels asked.
void handle_recording(GuiState& s, Recorder& rec) {
  std::string err;
  if (s.requests.start_recording && !s.recording) {
    if (!(s.record_every > 0.0)) {
      s.notify("recording: 'every' must be a positive time interval", true);
    } else if (rec.start(s.record_dir, &err)) {
      s.recording = true;
      s.set_record_interval(s.record_every);
      s.notify("recording into " + s.record_dir + "/" +
               (rec.first() > 0 ? " after its frame_" + std::to_string(rec.first() - 1) + ".png" : std::string()));
    } else {
      s.notify("recording: " + err, true);
    }
  }
  if (s.requests.stop_recording && s.recording) {
    s.recording = false;
    s.set_record_interval(0.0);
    rec.stop();
    s.notify("wrote " + std::to_string(rec.frames()) + " frames to " + rec.dir() + "/");
  }
  s.requests.start_recording = s.requests.stop_recording = false;
}

/// Ctrl+= / Ctrl+- (and the keypad's + and -) step the UI scale, Ctrl+0 resets it; Ctrl+S saves the
/// state to the State panel's file.
void ctrl_keys(GuiState& s, const std::vector<int>& ctrl_presses) {
  for (int key : ctrl_presses) {
    if (key == GLFW_KEY_S) s.save_state(s.state_path);
    if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD) s.look.scale = step_ui_scale(s.look.scale, 1);
    if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) s.look.scale = step_ui_scale(s.look.scale, -1);
    if (key == GLFW_KEY_0 || key == GLFW_KEY_KP_0) s.look.scale = kUiScaleMin;
  }
}

/// Applies the look the panels or keys asked for (between frames: the font atlas is rebuilt); the plot's
/// own text follows the scale unless its size was chosen.
void apply_look(GuiState& s, UiLook* applied) {
  if (s.look == *applied) return;
  bool fallback = false;
  s.look_text = apply_ui_look(s.look, true, &fallback);
  s.view.high_contrast = s.look.high_contrast;  // the particle view's axes, labels and legends too
  if (s.look.scale != applied->scale && (s.view.text_scale == 0 || s.view.text_scale == static_cast<int>(std::lround(applied->scale))))
    s.view.text_scale = s.look.scale > 1.f ? static_cast<int>(std::lround(s.look.scale)) : 0;
  char b[64];
  std::snprintf(b, sizeof b, "UI scale %.2fx%s: ", s.look.scale, s.look.high_contrast ? ", high contrast" : "");
  s.notify(b + s.look_text, fallback);
  *applied = s.look;
}

/// Input and the engine's news: events and key taps, the UI look, the state's update and pace, the
/// recorded frame. Returns the newest frame (null before the first).
const StepperFrame* take_input(MainLoop& l) {
  GuiState& state = l.state;
  glfwPollEvents();
  tap_keys_hook(l.o, l.stats.frames(), l.window);
  state.key_presses = l.window.take_key_presses();
  ctrl_keys(state, l.window.take_ctrl_presses());
  apply_look(state, &l.applied);
  state.update();
  l.pace.see(state);
  state.pace_note = l.pace.note(state);
  const StepperFrame* f = state.frame();
  if (f) l.engine_rate.see(*f);
  if (f && state.fresh() && f->record_index >= 0 && l.recorder.active() &&
      !l.recorder.write(l.view, view_scene(*f), state.view, state.record_width, state.record_height, &l.err)) {
    state.notify("recording stopped: " + l.err, true);
    state.requests.stop_recording = true;
    l.rc = kIoError;
  }
  return f;
}

/// This frame's panels (ImGui's draw data, rendered) and the view's mouse; sets *shown to the frame the
/// view shows (a stored one while scrubbing). Returns the layout.
Layout build_ui(MainLoop& l, const StepperFrame* f, const StepperFrame** shown_out) {
  GuiState& state = l.state;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  click_hook(l.o, l.stats.frames(), l.view, l.last_view_rect);
  push_drag_hook(l.o, l.stats.frames(), l.view, l.last_view_rect);
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();
  Layout L = compute_layout(static_cast<int>(io.DisplaySize.x), static_cast<int>(io.DisplaySize.y),
                            ImGui::GetFontSize(), ImGui::GetStyle().WindowPadding.y);
  if (state.inspect_id >= 0) carve_inspector(L, ImGui::GetFontSize());
  draw_panels(state, L, l.stats);
  if (!io.WantTextInput && std::count(state.key_presses.begin(), state.key_presses.end(), GLFW_KEY_F12))
    state.requests.screenshot = true;
  const StepperFrame* shown = state.shown_frame();  // a stored frame while scrubbing
  if (shown) l.view.interact(to_framebuffer(L.view), shown->snapshot, &state.view);
  if (shown) pick_particles(state, l.view, to_framebuffer(L.view));
  push_particles(state, l.view, to_framebuffer(L.view));
  if (!f || state.building()) {  // World construction can take seconds (10^5 particles)
    const std::string text = "building " + state.scene_name() + " ...";
    ImGui::GetBackgroundDrawList()->AddText(ImVec2(L.view.x + 20.f, L.view.y + L.view.h - 2.f * ImGui::GetFontSize()),
                                            IM_COL32(255, 200, 90, 255), text.c_str());
  }
  ImGui::Render();
  *shown_out = shown;
  return L;
}

/// The recording started or stopped as asked, the screenshot asked for (F12, the button) and --screenshot
/// at the last frame.
void save_pictures(MainLoop& l, const StepperFrame* f, int fw, int fh, bool last) {
  GuiState& state = l.state;
  handle_recording(state, l.recorder);
  if (state.requests.screenshot) {
    state.requests.screenshot = false;
    const std::string path = unique_path(
        "sph-gui_" + (f ? f->snapshot.scene + "_step" + std::to_string(f->snapshot.step) : "empty"), ".png");
    if (screenshot(path, fw, fh, &l.err)) state.notify("wrote " + path);
    else state.notify(l.err, true);
  }
  if (last && !l.o.screenshot.empty() && !screenshot(l.o.screenshot, fw, fh, &l.err)) {
    std::fprintf(stderr, "sph-gui: %s\n", l.err.c_str());
    l.rc = kIoError;
  }
}

}  // namespace

/// One displayed frame; true when it was the last (--quit-after-frames, --quit-at-end).
bool display_frame(MainLoop& l) {
  const GuiOptions& o = l.o;
  GuiState& state = l.state;
  const StepperFrame* f = take_input(l);
  const StepperFrame* shown = nullptr;
  const Layout L = build_ui(l, f, &shown);

  // Draw only when something on screen changes: the panels' draw data, the particle view, the size,
  // or a damaged window; or when pixels are wanted. Otherwise the last picture stays up (idle frame).
  int fw = 0, fh = 0;
  l.window.framebuffer_size(&fw, &fh);
  const Rect view_rect = to_framebuffer(L.view);
  l.last_view_rect = view_rect;
  const std::uint64_t ui = draw_data_hash(*ImGui::GetDrawData());
  bool last = (o.quit_after_frames > 0 && l.stats.frames() + 1 >= o.quit_after_frames) || l.end_shown;
  // the layout report reads a settled frame: one where no window still waits for its scroll bar or size
  if (last && o.layout_report && !layout_settled() && l.settle_frames < 10) {
    last = false;
    ++l.settle_frames;
  }
  const render::FrameScene scene = shown ? view_scene(*shown) : render::FrameScene{};
  const bool draw = o.always_redraw || l.stats.frames() < 2 || ui != l.last_ui || fw != l.last_fw ||
                    fh != l.last_fh || l.window.take_damage() ||
                    (shown && l.view.stale(shown->serial, state.view, scene.highlight, view_rect)) ||
                    state.requests.screenshot || (last && !o.screenshot.empty());
  if (draw) {
    glViewport(0, 0, fw, fh);
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    glClearColor(bg.x, bg.y, bg.z, 1.f);  // the panels' background (they draw none themselves)
    glClear(GL_COLOR_BUFFER_BIT);
    if (shown) l.view.draw(scene, shown->serial, state.view, view_rect, fh);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  l.last_ui = ui;
  l.last_fw = fw;
  l.last_fh = fh;
  save_pictures(l, f, fw, fh, last);
  if (draw) glfwSwapBuffers(l.window.handle());
  l.stats.frame_done(draw);

  if (last) return true;
  scrub_back_hook(o, f, state);  // test hook: look back
  l.end_shown = o.quit_at_end && f && f->at_end && !state.building() && (o.scrub_back == 0 || state.scrub >= 0) &&
                (o.compare_sets.empty() || f->comparing) && (o.sweep.empty() || !f->sweep.empty()) && (state.inspect_id < 0 || (f->inspection &&
                f->inspection->step == f->snapshot.step)) && !l.view.stale(shown->serial, state.view, scene.highlight, view_rect) &&
                l.view.shows(shown->serial);  // not a rate-limited older picture (a stale --quit-at-end screenshot)
  return false;
}

}  // namespace sph::gui
