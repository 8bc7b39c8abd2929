// What sph-gui prints when it exits, for scripted checks: frames and rates, the recording, the last state,
// the view's legend and inspected particle, pushes, the scrubbed frame, the UI look, the pace, and the
// lesson step's check.
#pragma once
#include "engine_rate.h"
#include "frame_stats.h"
#include "gui_state.h"
#include "particle_view.h"
#include "recorder.h"
#include "ui_look.h"

namespace sph::gui {

/// The last frame's text that is clipped or overlaps other text (--layout-report; layout_check.h).
void report_layout(const ParticleView& view, const GuiState& state);

/// The exit report on stdout; `applied` is the UI look in use, `threads` the engine's. Waits for the
/// lesson step's check.
void report_exit(GuiState& state, const ParticleView& view, const Recorder& recorder, const FrameStats& stats,
                 const EngineRate& engine_rate, const UiLook& applied, int threads);

}  // namespace sph::gui
