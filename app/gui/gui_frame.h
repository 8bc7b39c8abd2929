// One displayed frame of sph-gui's main loop (shaped like imgui's example_glfw_opengl3: poll, new frame,
// panels, render, swap): input and the engine's news, the panels, drawing only when something on screen
// changed, screenshots and recording.
#pragma once
#include <cstdint>
#include <string>

#include "auto_pace.h"
#include "engine_rate.h"
#include "frame_stats.h"
#include "gui_app.h"
#include "gui_options.h"
#include "gui_state.h"
#include "layout.h"
#include "particle_view.h"
#include "recorder.h"
#include "ui_look.h"
#include "window.h"

namespace sph::gui {

/// What the main loop works with, and what it keeps from one displayed frame to the next.
struct MainLoop {
  const GuiOptions& o;
  Window& window;
  ParticleView& view;
  GuiState& state;
  Recorder& recorder;
  FrameStats& stats;
  EngineRate& engine_rate;
  AutoPace& pace;
  UiLook& applied;
  std::string& err;
  int rc = kOk;
  std::uint64_t last_ui = 0;  // draw-data fingerprint of the last drawn frame
  int last_fw = 0, last_fh = 0;
  bool end_shown = false;     // --quit-at-end: the view showed the state at t_end (quit at the next frame)
  int settle_frames = 0;      // --layout-report: frames added at the end for the layout to settle (at most 10)
  Rect last_view_rect{};      // where the view was drawn last frame [framebuffer px]
};

/// One displayed frame; true when it was the last (--quit-after-frames, --quit-at-end).
bool display_frame(MainLoop& l);

}  // namespace sph::gui
