// The GUI's side of the engine <-> app channels (main thread only): its own edit copies of the params,
// scene values and view settings; what it has asked the stepper for; and the frame it is showing.
// Panels read and edit this; they reach the engine only through the methods below.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sph/config.h"
#include "lesson_ui.h"
#include "push_drag.h"
#include "recent_files.h"
#include "snapshot_ring.h"
#include "ui_look.h"
#include "sph/stepper.h"
#include "view_settings.h"

namespace sph::gui {

/// Things a panel asks for that the main loop does at the end of the frame (they need GL or files).
struct Requests {
  bool screenshot = false;    ///< write the whole window to a PNG
  bool start_recording = false;
  bool stop_recording = false;
};

class ConvergeJob;

/// The convergence panel's fields and its running or finished study.
struct ConvergeUi {
  std::string scene;  ///< the scene the fields were filled for
  std::string key, values, column, message;
  double t = 0.0;
  std::shared_ptr<ConvergeJob> job;
};

class GuiState {
 public:
  GuiState(Stepper& stepper, const RunConfig& initial);

  /// Takes the newest frame (once per display frame) and re-syncs the edit copies after a rebuild.
  void update();
  /// The frame shown this display frame (nullptr until the first World is built).
  const StepperFrame* frame() const { return frame_; }
  /// The frame the particle view draws: a stored one while scrubbing (view-only), else frame().
  const StepperFrame* shown_frame() const;
  SnapshotRing ring;               ///< the last frames shown, for pause and scrub
  int scrub = -1;                  ///< index into ring shown by the view; -1: the live frame
  /// The frame is new this display frame (its serial changed).
  bool fresh() const { return fresh_; }
  /// A load or reset has been sent and its World is not built yet.
  bool building() const { return awaiting_ != 0; }
  /// The scene being built or shown.
  const std::string& scene_name() const { return scene_name_; }

  // --- params (channel 1) ----------------------------------------------------------------------------
  Params edit;              ///< what the parameter widgets show
  SceneValues values;       ///< what the scene-value widgets show
  /// Hands `edit` to the mailbox; fields that need a reset keep the engine's values until then.
  void post_live();
  /// Structural edits not yet applied: "gamma 1.4 -> 1.67", "scene.n_left 400 -> 800".
  std::vector<std::string> pending() const;

  // --- commands (channel 2) --------------------------------------------------------------------------
  /// Rebuilds the World at t = 0 with the edited params and scene values (applies pending edits).
  void reset();
  /// Loads another scene (its defaults, or a file's); the edit copies follow once it is built. A pause
  /// time (set_pause_at) ends with the scene it was set for.
  void load(const RunConfig& cfg);
  void pause() { stepper_.pause(); }
  /// Play; at t_end with "stop at t_end" on, play replays the run from t = 0.
  void resume();
  void step_once() { stepper_.step_once(); }
  void set_real_time_factor(double f);
  void set_stop_at_end(bool on);
  /// Pause when the run reaches time t (a lesson step's pause_at; Play runs on); t <= 0: never.
  void set_pause_at(double t) {
    pause_at = t > 0.0 ? t : 0.0;
    stepper_.set_pause_at(pause_at);
  }
  /// Frames carry particle k's Barnes-Hut walk (the tree overlay); k < 0 turns it off.
  void set_tree_probe(std::int64_t k);
  void set_record_interval(double every) { stepper_.set_record_interval(every); }
  /// A/B comparison: both runs restart from t = 0, run B with these overrides (key=value); empty: stop.
  void set_compare(const std::vector<std::string>& overrides) { stepper_.set_compare(overrides); }
  /// A parameter sweep: run A and one more run per value of `key`, from t = 0 (Stepper::set_sweep).
  void set_sweep(const std::string& key, const std::vector<std::string>& values) { stepper_.set_sweep(key, values); }
  /// Writes the World's whole state to `path` (a checkpoint: `sph run --checkpoint-every`'s format).
  void save_state(const std::string& path);
  /// Replaces the World by the state in checkpoint `path` (saved here or by `sph run`); a file that is
  /// not a readable checkpoint is refused with a message naming it, and the run on screen stays.
  /// Returns false (and says why in `message`) if the file was refused.
  bool load_state(const std::string& path);
  std::string state_path = "state.sph";  ///< the state panel's file
  /// The particle inspector shows particle `id` (< 0: closes it).
  void inspect(std::int64_t id);
  /// The user's push on run A from its next step (sph/push.h); an inactive push ends it.
  void set_push(const Push& p) { stepper_.set_push(p); }
  PushDrag push;                   ///< the right-drag push: its settings and the drag in progress
  std::int64_t inspect_id = -1;    ///< as last sent (-1: the inspector is closed)
  /// Where the Parameters header was drawn (its y in the controls' content [px]) while the run ran and
  /// while it was stopped: the same when the rows above keep their place (a click meant for visc.beta
  /// landed on visc.alpha when the scrub row went away at a stop); --layout-report prints both.
  struct RowPlace {
    float running = -1.f, stopped = -1.f;  ///< -1: not seen
  } params_row;
  std::string compare_text = "kernel.type=M6";  ///< the compare panel's overrides, comma-separated
  std::string sweep_key = "kernel.eta", sweep_values = "1.0, 1.5";  ///< the sweep panel's key and values
  double real_time_factor = 0.0;   ///< as last sent (0 = as fast as possible)
  bool stop_at_end = true;         ///< as last sent
  double pause_at = 0.0;           ///< as last sent (0: no pause time)
  std::int64_t tree_probe = -1;    ///< as last sent (-1: no tree overlay)
  ConvergeUi converge;             ///< the convergence study panel
  LessonUi lesson;                 ///< the lesson panel
  UiLook look;                     ///< projector mode: asked for (the main loop applies it between frames)
  std::string look_text;           ///< what the last applied look loaded ("DejaVuSans.ttf at 32 px")
  std::string pace_note;           ///< the status line's note on an automatic pace (auto_pace.h)
  std::shared_ptr<RecentFiles> recent;  ///< scene files opened, newest first
  /// Loads a scene file (JSON or HDF5) and puts it first in the recent files; false with a notice.
  bool open_file(const std::string& path);
  int tree_probe_pick = 0;         ///< the particle the overlay shows when switched on

  // --- view and user requests --------------------------------------------------------------------------
  render::ViewSettings view;
  Requests requests;
  std::vector<int> key_presses;    ///< this frame's key presses (GLFW codes, in order): Window::take_key_presses
  std::string file_path;           ///< scene file path typed in the scene panel
  std::string message;             ///< last notice (file written, load error)
  bool message_is_error = false;
  void notify(std::string text, bool error = false);

  // recording settings (the main loop's Recorder does the writing)
  bool recording = false;
  std::string record_dir = "frames";
  double record_every = 0.01;
  int record_width = 1280, record_height = 720;

  /// The help window (F1 or H): sph/help_text.h's scene_help for the scene on screen and the values being
  /// edited, rebuilt only when they change.
  struct HelpView {
    bool open = false;
    const SceneSpec* scene = nullptr;
    Params params;
    SceneValues values;
    std::string text;
  } help;

  std::uint64_t acknowledged_divergence = 0;  ///< world_serial whose divergence dialog was closed
  std::string param_error;                    ///< why the last typed parameter value was refused

  /// Kernel explorer choices.
  struct KernelView {
    bool follow = true;                    ///< show the run's kernel
    KernelType kernel = KernelType::M4;    ///< else this one
    int dim = 0;                           ///< 1, 2, 3; 0 = the scene's dimension
  } kernel_view;

 private:
  void resync_from(const StepperFrame& f);
  Stepper& stepper_;
  const StepperFrame* frame_ = nullptr;
  std::uint64_t serial_ = 0, world_serial_ = 0;
  std::uint64_t resync_version_ = 1;  // take params/values from the first frame that adopted this version
  std::uint64_t awaiting_ = 1;        // a rebuild with this params version is on its way
  std::string scene_name_;
  std::string last_error_;            // the frame error last reported
  std::string last_notice_;           // the frame notice last reported (state saved or loaded)
  bool fresh_ = false;
};

}  // namespace sph::gui
