// The ImGui panels, one file each. Each draws into the current window (or opens its own, for the modal)
// and reaches the engine only through GuiState.
#pragma once
#include "gui_state.h"
#include "layout.h"

namespace sph::gui {

class FrameStats;

/// All tiled windows at their places in the layout, and the divergence dialog.
void draw_panels(GuiState& s, const Layout& layout, const FrameStats& stats);

void panel_scene(GuiState& s);        ///< scene picker, JSON file, scene values (needs reset)
void panel_run(GuiState& s);          ///< play/pause/step/reset, pacing, screenshot, recording
void panel_params(GuiState& s);       ///< live run parameters from sph::param_table()
void panel_display(GuiState& s);      ///< colour by, colour map, range, particle size, camera
void panel_diagnostics(GuiState& s);  ///< energies, momentum, L1 error against time
void panel_converge(GuiState& s);     ///< convergence study of the current scene (sph converge)
void panel_kernel(GuiState& s);       ///< kernel explorer: W(q), dW/dq against the Gaussian
void panel_compare(GuiState& s);      ///< A/B comparison: run B's overrides, start and stop
void panel_sweep(GuiState& s);        ///< a parameter sweep: its key and values, start and stop
void panel_state(GuiState& s);        ///< save the run's whole state to a checkpoint file, or load one
void panel_inspector(GuiState& s);    ///< the picked particle: fields, equation terms, neighbours
void status_line(GuiState& s, const FrameStats& stats);  ///< t, dt, steps/s, neighbours, h-iterations
void divergence_modal(GuiState& s);   ///< after a NaN/inf: which particle and step, and a reset button
void panel_help(GuiState& s);         ///< F1 / H: the keys and mouse actions, and `sph help SCENE` for the scene on screen
void panel_lesson(GuiState& s);       ///< a lesson's steps, previous/next, the step's check in green or red

/// Opens a lesson file on step `step` (0-based, clamped) and loads that step; false (with a notice) if the
/// file is malformed.
bool open_lesson(GuiState& s, const std::string& path, int step);
/// Shows step `step` of the open lesson and loads its scene (and comparison).
void show_lesson_step(GuiState& s, int step);
/// Starts the current step's check (unless it is already running).
void check_lesson_step(GuiState& s);
/// The Lesson panel's editor: the run on screen as a step of a new lesson, saved as a lesson file.
void lesson_editor(GuiState& s);

}  // namespace sph::gui
