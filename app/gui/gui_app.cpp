// sph-gui's program: the scene resolved, the window, the view, the stepper and the state set up from the
// options, the main loop (gui_frame.h) until the window closes, and the exit report (gui_report.h).
#include "gui_app.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "auto_pace.h"
#include "engine_rate.h"
#include "frame_stats.h"
#include "gui_frame.h"
#include "gui_report.h"
#include "gui_state.h"
#include "overrides_text.h"
#include "panels.h"
#include "particle_view.h"
#include "recorder.h"
#include "sph/compare.h"
#include "sph/config.h"
#include "sph/key_value.h"
#include "sph/stepper.h"
#include "ui_look.h"
#include "window.h"

namespace sph::gui {
namespace {

RunConfig resolve(const GuiOptions& o) {
  RunConfig cfg = RunConfig::load(o.scene);
  for (const std::string& kv : o.sets) apply_key_value(cfg, "--set", kv);
  return cfg;
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

/// The engine's threads and start: all cores but one (the display's) unless --threads; --record's frames.
StepperOptions stepper_options(const GuiOptions& o) {
  StepperOptions so;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  so.threads = o.threads > 0 ? o.threads : std::max(1, cores - 1);  // one core stays with the display
  if (so.threads >= cores) so.nice = 5;  // the engine takes every core: let the display go first
  so.start_running = !o.paused;
  if (!o.record.empty()) so.record_every = o.record_every;  // frames from t = 0, like `sph run --frames`
  return so;
}

/// --sweep KEY=V1,V2,...: kOk, or after a message naming it kUsage (not KEY=values, more than 5 values) or
/// kInvalidScene (a key or value the scene refuses), before any window opens.
int check_sweep(const GuiOptions& o, const RunConfig& cfg) {
  if (o.sweep.empty()) return kOk;
  std::string key, err;
  std::vector<std::string> values;
  if (!split_sweep(o.sweep, &key, &values, &err)) {
    std::fprintf(stderr, "sph-gui: --sweep: %s\n", err.c_str());
    return kUsage;
  }
  try {
    for (const std::string& v : values) (void)fork_config(cfg, {key + "=" + v});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph-gui: --sweep: %s\n", e.what());
    return kInvalidScene;
  }
  return kOk;
}

/// The state the options start from: tree probe, comparison, inspector, a saved state, profile panels,
/// recent files, the lesson; kOk, or the exit code after a message.
int start_state(const GuiOptions& o, GuiState& state) {
  if (o.tree_probe >= 0) state.set_tree_probe(o.tree_probe);
  if (!o.compare_sets.empty()) state.set_compare(o.compare_sets);
  if (!o.sweep.empty()) {  // checked by check_sweep
    std::string key, err;
    std::vector<std::string> values;
    if (split_sweep(o.sweep, &key, &values, &err)) state.set_sweep(key, values);
  }
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
  return kOk;
}

/// --record DIR: the stepper already records; opens the directory. False after a message.
bool start_record(const GuiOptions& o, GuiState& state, Recorder& recorder, std::string& err) {
  state.record_dir = o.record;
  state.record_every = o.record_every;
  parse_size(o.record_size, &state.record_width, &state.record_height);
  if (!recorder.start(o.record, &err)) {
    std::fprintf(stderr, "sph-gui: --record: %s\n", err.c_str());
    return false;
  }
  state.recording = true;
  return true;
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
  if (const int rc = check_sweep(o, cfg); rc != kOk) return rc;
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
  const StepperOptions so = stepper_options(o);
  Stepper stepper(cfg, so);
  GuiState state(stepper, cfg);
  Recorder recorder;
  FrameStats stats(o.max_fps);
  EngineRate engine_rate;
  if (const int rc = start_state(o, state); rc != kOk) return rc;
  UiLook applied;  // the window starts at scale 1, the dark theme
  state.look = UiLook{o.ui_scale, o.high_contrast};
  if (window->font_fallback()) state.notify("font " + ui_font_path() + " not found: ImGui's built-in font", true);
  const bool scripted = o.quit_after_frames > 0 || o.quit_at_end || !o.record.empty() || !o.screenshot.empty() ||
                        !o.tap_keys.empty();
  AutoPace pace(o.auto_pace == 1 || (o.auto_pace < 0 && !scripted));
  if (!o.record.empty() && !start_record(o, state, recorder, err)) return kIoError;

  MainLoop loop{o, *window, view, state, recorder, stats, engine_rate, pace, applied, err};
  while (!window->should_close())
    if (display_frame(loop)) break;
  report_exit(state, view, recorder, stats, engine_rate, applied, so.threads);
  if (o.layout_report) report_layout(view, state);
  return loop.rc;
}

}  // namespace sph::gui
