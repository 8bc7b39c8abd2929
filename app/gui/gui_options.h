// Command line of sph-gui: what to load, how big, and the scripting hooks used by CI (screenshot,
// quit after N frames) and by measurements (engine threads, frame-rate cap).
#pragma once
#include <string>
#include <vector>

namespace sph::gui {

struct GuiOptions {
  std::string scene = "sod";         ///< built-in scene name or JSON scene file
  std::vector<std::string> sets;     ///< --set key=value overrides, as in `sph run`
  std::string screenshot;            ///< PNG of the whole window, taken at the last frame
  int quit_after_frames = 0;         ///< exit after this many displayed frames (0 = run until closed)
  int width = 1600, height = 900;    ///< window size [px] (clamped to the screen)
  int threads = 0;                   ///< engine OpenMP threads; 0 = all cores but one (at least 1)
  double max_fps = 60.0;             ///< display frame-rate cap [1/s]; 0 = uncapped
  double view_fps = 60.0;            ///< new snapshots drawn at most this often [1/s]; 0 = no limit
                                     ///< (also at most a third of the time goes to drawing the view)
  bool paused = false;               ///< start paused
  bool always_redraw = false;        ///< draw every frame even when nothing on screen changes (benchmarks)
  std::string record;                ///< start recording PNG frames into this directory
  std::string load_state;            ///< start from the state in this checkpoint (sph run --checkpoint-every)
  double record_every = 0.01;        ///< simulated time between recorded frames [time units]
  std::string record_size = "1280x720";  ///< recorded frame size WIDTHxHEIGHT
  /// Test hook: FRAME:KEYS taps every key of KEYS (letters, ' ' for Space) at displayed frame FRAME, all
  /// between the same two frames (the quick taps a key-state poll would lose).
  std::vector<std::string> tap_keys;
  long long tree_probe = -1;         ///< start with the tree overlay of this particle (tree-gravity scenes)
  std::string sweep;                       ///< start a parameter sweep: "KEY=V1,V2,..." (one more run per value)
  std::vector<std::string> compare_sets;  ///< start an A/B comparison: run B with these key=value overrides
  long long inspect = -1;            ///< open the particle inspector on this id
  std::string panels;                ///< profiles: one panel per field, comma-separated ("rho,v,p,u")
  /// Test hook: quit (after --screenshot) once the run is at t_end and the view shows that state (and
  /// the inspection and the comparison asked for have arrived); --quit-after-frames stays a limit.
  bool quit_at_end = false;
  /// Test hook: FRAME:ID presses the left mouse button on particle ID's dot at displayed frame FRAME and
  /// releases it at the next (a click through the view's picking, as a user's).
  std::vector<std::string> click_particles;
  /// Test hook: F0:F1:X0,Y0:X1,Y1 holds the right button from displayed frame F0 to F1 while the mouse
  /// moves evenly from world point (X0, Y0) to (X1, Y1), as a user's push (view_push.h).
  std::vector<std::string> push_drags;
  std::string lesson;                ///< open this lesson file (assets/lessons/*.json)
  int lesson_step = 1;               ///< on this step (1-based)
  bool lesson_check = false;         ///< run the step's check at once; its result is printed at exit
  float ui_scale = 1.f;              ///< projector mode: text and widgets at this scale (1-3)
  bool high_contrast = false;        ///< the high-contrast theme
  bool layout_report = false;        ///< at exit, check the last frame's text for clipping and overlaps
  /// Slow scenes that would reach t_end in under 4 s of wall time to about 8 s: -1 = unless the run
  /// is scripted (--quit-after-frames, --quit-at-end, --record, --screenshot, --tap-keys), 0 off, 1 on.
  int auto_pace = -1;
  int scrub_back = 0;                ///< test hook: at t_end, the view shows the frame this many back (scrub)
  std::string config_dir;            ///< where recent.json lives (default $XDG_CONFIG_HOME/sph-sandbox)
};

/// Parses argv. Returns -1 to go on, or the exit code (0 after --help, 2 on a usage error).
int parse_options(int argc, char** argv, GuiOptions* out);

/// "1280x720" -> 1280, 720; false if malformed or not positive.
bool parse_size(const std::string& text, int* w, int* h);

}  // namespace sph::gui
