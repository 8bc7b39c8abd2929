#include "gui_app.h"

#include "gui_gl.h"  // first: GL prototypes before any other glcorearb.h include

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "auto_pace.h"
#include "draw_data_hash.h"
#include "lesson_job.h"
#include "engine_rate.h"
#include "frame_stats.h"
#include "gui_state.h"
#include "layout.h"
#include "panels.h"
#include "particle_view.h"
#include "png_writer.h"
#include "recorder.h"
#include "unique_path.h"
#include "sph/config.h"
#include "sph/key_value.h"
#include "sph/stepper.h"
#include "overrides_text.h"
#include "view_picking.h"
#include "view_push.h"
#include "view_scene.h"
#include "view_target.h"
#include "ui_look.h"
#include "window.h"

namespace sph::gui {
namespace {

constexpr int kOk = 0, kNoDisplay = 1, kInvalidScene = 3, kIoError = 4, kBadLesson = 6;  // as the headless `sph`

RunConfig resolve(const GuiOptions& o) {
  RunConfig cfg = RunConfig::load(o.scene);
  for (const std::string& kv : o.sets) apply_key_value(cfg, "--set", kv);
  return cfg;
}

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
      s.notify("recording into " + s.record_dir + "/");
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

/// Test hook --click-particle FRAME:ID: the mouse on particle ID's dot, pressed at FRAME, released at the
/// next frame (ImGui's input for this frame, after the GLFW backend filled it).
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

/// Test hook --push-drag F0:F1:X0,Y0:X1,Y1: the right button held from displayed frame F0 to F1 while the
/// mouse moves evenly from world point (X0, Y0) to (X1, Y1) [length], released at F1.
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

/// What the view showed last, for scripted checks: its legend rows and the inspected particle's numbers
/// (17 digits: a test recomputes them with Report::inspect).
void report_view(const ParticleView& view, const StepperFrame& f) {
  std::string rows;
  for (const std::string& r : view.layout().legend_rows) rows += (rows.empty() ? "" : " | ") + r;
  if (!rows.empty()) std::printf("sph-gui: view legend: %s\n", rows.c_str());
  if (!f.inspection) return;
  const Inspection& in = *f.inspection;
  std::printf("sph-gui: inspected particle %lld at step %lld, t = %.17g: x = %.17g, rho = %.17g, u = %.17g, "
              "a_x = %.17g, du/dt = %.17g\n",
              static_cast<long long>(in.id), static_cast<long long>(in.step), in.t, in.x.x, in.rho, in.u, in.a_total.x,
              in.dudt_total);
  for (const InspectTerm& t : in.terms)
    std::printf("sph-gui: term %s: a_x = %.17g, du/dt = %.17g\n", t.name.c_str(), t.a.x, t.dudt);
}

/// Ctrl+= / Ctrl+- (and the keypad's + and -) step the UI scale, Ctrl+0 resets it.
void scale_keys(GuiState& s, const std::vector<int>& ctrl_presses) {
  for (int key : ctrl_presses) {
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
  if (s.look.scale != applied->scale && (s.view.text_scale == 0 || s.view.text_scale == static_cast<int>(std::lround(applied->scale))))
    s.view.text_scale = s.look.scale > 1.f ? static_cast<int>(std::lround(s.look.scale)) : 0;
  char b[64];
  std::snprintf(b, sizeof b, "UI scale %.2fx%s: ", s.look.scale, s.look.high_contrast ? ", high contrast" : "");
  s.notify(b + s.look_text, fallback);
  *applied = s.look;
}

/// --lesson FILE [--lesson-step N] [--lesson-check]: the lesson panel on that step; false if malformed.
bool start_lesson(const GuiOptions& o, GuiState& s) {
  if (o.lesson.empty()) return true;
  if (!open_lesson(s, o.lesson, o.lesson_step - 1)) {
    std::fprintf(stderr, "sph-gui: --lesson: %s\n", s.lesson.error.c_str());
    return false;
  }
  if (o.lesson_check) check_lesson_step(s);
  return true;
}

/// The lesson step's check at exit (waits for it): for scripted checks of the panel.
void report_lesson(GuiState& s) {
  LessonUi& L = s.lesson;
  if (!L.lesson || !L.job) return;
  L.job->wait();
  const int n = static_cast<int>(L.lesson->steps.size());
  if (!L.job->error().empty())
    std::printf("sph-gui: lesson step %d/%d: error: %s\n", L.job_step + 1, n, L.job->error().c_str());
  else if (L.job->result())
    std::printf("sph-gui: lesson step %d/%d: %s: %s\n", L.job_step + 1, n, L.job->result()->pass ? "true" : "FALSE",
                L.job->result()->text.c_str());
}

}  // namespace

int run_gui(const GuiOptions& o) {
  RunConfig cfg;
  try {
    cfg = resolve(o);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph-gui: invalid scene: %s\n", e.what());
    return kInvalidScene;
  }
  std::string err;
  auto window = Window::create(o.width, o.height, "SPH sandbox", &err);
  if (!window) {
    std::fprintf(stderr, "sph-gui: %s\n", err.c_str());
    return kNoDisplay;
  }
  ParticleView view(o.view_fps);  // GL objects: destroyed before the window (declared after it)
  if (!view.init(&err)) {
    std::fprintf(stderr, "sph-gui: renderer: %s\n", err.c_str());
    return kNoDisplay;
  }
  StepperOptions so;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  so.threads = o.threads > 0 ? o.threads : std::max(1, cores - 1);  // one core stays with the display
  if (so.threads >= cores) so.nice = 5;  // the engine takes every core: let the display go first
  so.start_running = !o.paused;
  if (!o.record.empty()) so.record_every = o.record_every;  // frames from t = 0, like `sph run --frames`
  Stepper stepper(cfg, so);
  GuiState state(stepper, cfg);
  Recorder recorder;
  FrameStats stats(o.max_fps);
  EngineRate engine_rate;
  if (o.tree_probe >= 0) state.set_tree_probe(o.tree_probe);
  if (!o.compare_sets.empty()) state.set_compare(o.compare_sets);
  if (o.inspect >= 0) state.inspect(o.inspect);
  if (!o.load_state.empty() && !state.load_state(o.load_state)) {
    std::fprintf(stderr, "sph-gui: %s\n", state.message.c_str());
    return kInvalidScene;
  }
  state.view.panels = split_overrides(o.panels);
  state.recent = std::make_shared<RecentFiles>(o.config_dir);
  if (!state.recent->error().empty()) state.notify(state.recent->error(), true);
  std::error_code ec;
  if (std::filesystem::is_regular_file(o.scene, ec)) state.recent->add(o.scene);  // a scene file opened
  if (!start_lesson(o, state)) return kBadLesson;
  UiLook applied;  // the window starts at scale 1, the dark theme
  state.look = UiLook{o.ui_scale, o.high_contrast};
  if (window->font_fallback()) state.notify("font " + ui_font_path() + " not found: ImGui's built-in font", true);
  const bool scripted = o.quit_after_frames > 0 || o.quit_at_end || !o.record.empty() || !o.screenshot.empty() ||
                        !o.tap_keys.empty();
  AutoPace pace(o.auto_pace == 1 || (o.auto_pace < 0 && !scripted));
  if (!o.record.empty()) {  // the stepper already records; open the directory
    state.record_dir = o.record;
    state.record_every = o.record_every;
    parse_size(o.record_size, &state.record_width, &state.record_height);
    if (!recorder.start(o.record, &err)) {
      std::fprintf(stderr, "sph-gui: --record: %s\n", err.c_str());
      return kIoError;
    }
    state.recording = true;
  }
  int rc = kOk;
  std::uint64_t last_ui = 0;  // draw-data fingerprint of the last drawn frame
  int last_fw = 0, last_fh = 0;
  bool end_shown = false;     // --quit-at-end: the view showed the state at t_end (quit at the next frame)
  Rect last_view_rect;        // where the view was drawn last frame [framebuffer px]

  while (!window->should_close()) {
    glfwPollEvents();
    for (const std::string& t : o.tap_keys) {  // test hook: taps through the key callback
      const auto colon = t.find(':');
      if (std::stoll(t.substr(0, colon)) != stats.frames()) continue;
      for (const char ch : t.substr(colon + 1)) {
        if (ch == '+' || ch == '-') window->tap_key(ch == '+' ? GLFW_KEY_EQUAL : GLFW_KEY_MINUS, GLFW_MOD_CONTROL);
        else window->tap_key(ch == ' ' ? GLFW_KEY_SPACE : std::toupper(ch));
      }
    }
    state.key_presses = window->take_key_presses();
    scale_keys(state, window->take_ctrl_presses());
    apply_look(state, &applied);
    state.update();
    pace.see(state);
    state.pace_note = pace.note(state);
    const StepperFrame* f = state.frame();
    if (f) engine_rate.see(*f);
    if (f && state.fresh() && f->record_index >= 0 && recorder.active() &&
        !recorder.write(view, view_scene(*f), state.view, state.record_width, state.record_height, &err)) {
      state.notify("recording stopped: " + err, true);
      state.requests.stop_recording = true;
      rc = kIoError;
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    click_hook(o, stats.frames(), view, last_view_rect);
    push_drag_hook(o, stats.frames(), view, last_view_rect);
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    Layout L = compute_layout(static_cast<int>(io.DisplaySize.x), static_cast<int>(io.DisplaySize.y),
                              ImGui::GetFontSize());
    if (state.inspect_id >= 0) carve_inspector(L, ImGui::GetFontSize());
    draw_panels(state, L, stats);
    if (!io.WantTextInput && std::count(state.key_presses.begin(), state.key_presses.end(), GLFW_KEY_F12))
      state.requests.screenshot = true;
    const StepperFrame* shown = state.shown_frame();  // a stored frame while scrubbing
    if (shown) view.interact(to_framebuffer(L.view), shown->snapshot, &state.view);
    if (shown) pick_particles(state, view, to_framebuffer(L.view));
    push_particles(state, view, to_framebuffer(L.view));
    if (!f || state.building()) {  // World construction can take seconds (10^5 particles)
      const std::string text = "building " + state.scene_name() + " ...";
      ImGui::GetBackgroundDrawList()->AddText(ImVec2(L.view.x + 20.f, L.view.y + L.view.h - 2.f * ImGui::GetFontSize()),
                                              IM_COL32(255, 200, 90, 255), text.c_str());
    }
    ImGui::Render();

    // Draw only when something on screen changes: the panels' draw data, the particle view, the size,
    // or a damaged window; or when pixels are wanted. Otherwise the last picture stays up (idle frame).
    int fw = 0, fh = 0;
    window->framebuffer_size(&fw, &fh);
    const Rect view_rect = to_framebuffer(L.view);
    last_view_rect = view_rect;
    const std::uint64_t ui = draw_data_hash(*ImGui::GetDrawData());
    const bool last = (o.quit_after_frames > 0 && stats.frames() + 1 >= o.quit_after_frames) || end_shown;
    const render::FrameScene scene = shown ? view_scene(*shown) : render::FrameScene{};
    const bool draw = o.always_redraw || stats.frames() < 2 || ui != last_ui || fw != last_fw || fh != last_fh ||
                      window->take_damage() || (shown && view.stale(shown->serial, state.view, scene.highlight, view_rect)) ||
                      state.requests.screenshot || (last && !o.screenshot.empty());
    if (draw) {
      glViewport(0, 0, fw, fh);
      const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
      glClearColor(bg.x, bg.y, bg.z, 1.f);  // the panels' background (they draw none themselves)
      glClear(GL_COLOR_BUFFER_BIT);
      if (shown) view.draw(scene, shown->serial, state.view, view_rect, fh);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    last_ui = ui;
    last_fw = fw;
    last_fh = fh;

    handle_recording(state, recorder);
    if (state.requests.screenshot) {
      state.requests.screenshot = false;
      const std::string path = unique_path(
          "sph-gui_" + (f ? f->snapshot.scene + "_step" + std::to_string(f->snapshot.step) : "empty"), ".png");
      if (screenshot(path, fw, fh, &err)) state.notify("wrote " + path);
      else state.notify(err, true);
    }
    if (last && !o.screenshot.empty() && !screenshot(o.screenshot, fw, fh, &err)) {
      std::fprintf(stderr, "sph-gui: %s\n", err.c_str());
      rc = kIoError;
    }
    if (draw) glfwSwapBuffers(window->handle());
    stats.frame_done(draw);

    if (last) break;
    if (o.scrub_back > 0 && f && f->at_end && !state.building() && state.scrub < 0 &&
        state.ring.size() > static_cast<std::size_t>(o.scrub_back))
      state.scrub = static_cast<int>(state.ring.size()) - 1 - o.scrub_back;  // test hook: look back
    end_shown = o.quit_at_end && f && f->at_end && !state.building() && (o.scrub_back == 0 || state.scrub >= 0) &&
                (o.compare_sets.empty() || f->comparing) && (state.inspect_id < 0 || (f->inspection &&
                f->inspection->step == f->snapshot.step)) && !view.stale(shown->serial, state.view, scene.highlight, view_rect);
  }

  const StepperFrame* f = state.frame();
  std::printf("sph-gui: %lld frames in %.2f s: %.1f display fps (%.1f drawn/s); engine %.4g steps/s (%.3g "
              "particle-steps/s, %zu particles, %d threads)\n",
              static_cast<long long>(stats.frames()), stats.seconds(), stats.mean_fps(), stats.mean_drawn_fps(),
              engine_rate.rate(),
              engine_rate.rate() * static_cast<double>(f ? f->snapshot.count : 0), f ? f->snapshot.count : 0,
              so.threads);
  if (recorder.frames() > 0) std::printf("sph-gui: %d frames in %s/\n", recorder.frames(), recorder.dir().c_str());
  if (f) std::printf("sph-gui: last state: step %lld, t = %.9g\n", static_cast<long long>(f->snapshot.step), f->snapshot.t);
  if (f) report_view(view, *f);
  if (f && !f->pushes.empty())
    std::printf("sph-gui: pushes: %zu changes logged, %s; momentum P = (%.6g, %.6g)\n", f->pushes.size(),
                f->push.active() ? "one acting" : "none acting", f->diagnostics.P[0], f->diagnostics.P[1]);
  if (const StepperFrame* shown = state.shown_frame(); shown && shown != f)
    std::printf("sph-gui: view shows stored frame %d of %zu: step %lld, t = %.9g\n", state.scrub + 1, state.ring.size(),
                static_cast<long long>(shown->snapshot.step), shown->snapshot.t);
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  std::printf("sph-gui: ui: scale %.2f%s, %s, font %.0f px, atlas %d x %d\n", applied.scale,
              applied.high_contrast ? ", high contrast" : "", state.look_text.empty() ? "start font" : state.look_text.c_str(),
              ImGui::GetFontSize(), atlas.TexWidth, atlas.TexHeight);
  if (!state.pace_note.empty()) std::printf("sph-gui: pace: %s\n", state.pace_note.c_str());
  report_lesson(state);
  return rc;
}

}  // namespace sph::gui
