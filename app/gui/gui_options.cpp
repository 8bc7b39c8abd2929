#include "gui_options.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "frame_size.h"
#include "parse_command_line.h"

namespace sph::gui {

namespace {

/// The test hooks' and --record-size's syntax: 2 after a message on the first malformed one, else -1.
int check_syntax(const GuiOptions& o) {
  for (const std::string& t : o.tap_keys) {
    const auto colon = t.find(':');
    if (colon == std::string::npos || colon == 0 || t.find_first_not_of("0123456789") != colon) {
      std::fprintf(stderr, "sph-gui: --tap-keys %s: expected FRAME:KEYS, e.g. 5:SSS\n", t.c_str());
      return 2;
    }
  }
  for (const std::string& c : o.click_particles) {
    const auto colon = c.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == c.size() ||
        c.find_first_not_of("0123456789:") != std::string::npos || c.find(':', colon + 1) != std::string::npos) {
      std::fprintf(stderr, "sph-gui: --click-particle %s: expected FRAME:ID, e.g. 20:300\n", c.c_str());
      return 2;
    }
  }
  for (const std::string& d : o.push_drags) {
    long long f0 = 0, f1 = 0;
    double x[4];
    char tail = 0;
    if (std::sscanf(d.c_str(), "%lld:%lld:%lf,%lf:%lf,%lf%c", &f0, &f1, &x[0], &x[1], &x[2], &x[3], &tail) != 6 ||
        f0 < 0 || f1 <= f0) {
      std::fprintf(stderr, "sph-gui: --push-drag %s: expected F0:F1:X0,Y0:X1,Y1 with F0 < F1, e.g. 30:90:0.2,0.4:0.45,0.4\n",
                   d.c_str());
      return 2;
    }
  }
  int w = 0, h = 0;
  if (!parse_size(o.record_size, &w, &h) || w % 2 || h % 2) {
    std::fprintf(stderr, "sph-gui: --record-size %s: expected even WIDTHxHEIGHT, e.g. 1280x720\n",
                 o.record_size.c_str());
    return 2;
  }
  return -1;
}

}  // namespace

bool parse_size(const std::string& text, int* w, int* h) { return render::parse_frame_size(text, w, h); }

int parse_options(int argc, char** argv, GuiOptions* out) {
  GuiOptions& o = *out;
  CLI::App app{"sph-gui: the SPH sandbox on the desktop. The engine steps on its own thread; change the\n"
               "parameters while it runs, colour by any field, compare with the exact solution.\n"
               "Exit codes: 0 ok, 1 no display or GL 3.3, 2 usage error, 3 invalid scene, 4 I/O error,\n"
               "6 malformed lesson file (--lesson)."};
  std::string size;
  app.add_option("--scene", o.scene, "built-in scene name (see `sph list`) or JSON scene file")->capture_default_str();
  app.add_option("--set", o.sets, "override a parameter: key=value (repeatable), e.g. scene.count=100000");
  app.add_option("--screenshot", o.screenshot, "write a PNG of the whole window at the last frame");
  app.add_option("--quit-after-frames", o.quit_after_frames, "exit after N displayed frames")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--size", size, "window size WIDTHxHEIGHT (default 1600x900, clamped to the screen)");
  app.add_option("--threads", o.threads, "engine OpenMP threads (default: all cores but one)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--max-fps", o.max_fps, "display frame-rate cap, 0 = none")->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--view-fps", o.view_fps, "draw new snapshots at most this often (and in at most a third of the time), 0 = no limit")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_flag("--paused", o.paused, "start paused");
  app.add_option("--load-state", o.load_state,
                 "start from the state in this checkpoint (saved by the State panel, or OUT/checkpoint.sph of sph run)");
  app.add_option("--tree-probe", o.tree_probe, "start with the Barnes-Hut overlay of this particle (tree-gravity scenes)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--always-redraw", o.always_redraw,
               "render every frame, even when nothing on screen changed (to measure the drawing cost)");
  app.add_option("--record", o.record, "record PNG frames (frame_00000.png, ...) into this directory");
  app.add_option("--record-every", o.record_every, "simulated time between recorded frames")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--record-size", o.record_size, "recorded frame size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--compare-set", o.compare_sets,
                 "start an A/B comparison: run B is this run with key=value changed (repeatable), e.g. kernel.type=M6");
  app.add_option("--sweep", o.sweep,
                 "start a parameter sweep: run A beside one more run per value, KEY=V1,V2,... (at most 5), e.g. "
                 "kernel.eta=1.0,1.5; the profiles draw them all");
  app.add_option("--inspect", o.inspect, "open the particle inspector on this particle id")->check(CLI::NonNegativeNumber);
  app.add_option("--panels", o.panels, "profiles: one panel per field, e.g. rho,v,p,u (v: v_x in 1D)");
  app.add_flag("--quit-at-end", o.quit_at_end,
               "test hook: quit (after --screenshot) once the run has stopped at t_end and the view shows it");
  app.add_option("--click-particle", o.click_particles,
                 "test hook: FRAME:ID clicks particle ID's dot in the view at displayed frame FRAME (repeatable)");
  app.add_option("--push-drag", o.push_drags,
                 "test hook: F0:F1:X0,Y0:X1,Y1 right-drags (a push) from world point X0,Y0 to X1,Y1 over displayed "
                 "frames F0 to F1 (repeatable)");
  app.add_option("--tap-keys", o.tap_keys,
                 "test hook: FRAME:KEYS taps each key of KEYS (S, R, ' ' ...; + and - are Ctrl+= and Ctrl+-, ! Ctrl+S) at displayed "
                 "frame FRAME (repeatable)");
  app.add_option("--lesson", o.lesson, "open this lesson file (assets/lessons/*.json) in the Lesson panel");
  app.add_option("--lesson-step", o.lesson_step, "the lesson's step shown first (1-based)")->check(CLI::PositiveNumber);
  app.add_flag("--lesson-check", o.lesson_check, "run that step's check at once (its result is printed at exit)");
  app.add_option("--ui-scale", o.ui_scale, "projector mode: text and widgets at this scale, 1-3 (Ctrl+= / Ctrl+-)")
      ->check(CLI::Range(1.0, 3.0));
  app.add_flag("--high-contrast", o.high_contrast, "the high-contrast theme");
  app.add_flag("--layout-report", o.layout_report,
               "test hook: at exit, print the last frame's text that is clipped or overlaps other text");
  std::string pace;
  app.add_option("--auto-pace", pace, "on: slow a scene that would reach t_end in under 4 s of wall time to about 8 s "
                                      "(default: on unless the run is scripted); off: never")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--scrub-back", o.scrub_back, "test hook: once at t_end, scrub the view back this many stored frames")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--config-dir", o.config_dir, "folder of recent.json (default $XDG_CONFIG_HOME/sph-sandbox or "
                                               "~/.config/sph-sandbox)");
  if (const auto code = parse_command_line(app, argc, argv, 2)) return *code;
  if (!pace.empty()) o.auto_pace = pace == "on" ? 1 : 0;
  if (!size.empty() && !parse_size(size, &o.width, &o.height)) {
    std::fprintf(stderr, "sph-gui: --size %s: expected WIDTHxHEIGHT, e.g. 1600x900\n", size.c_str());
    return 2;
  }
  return check_syntax(o);
}

}  // namespace sph::gui
