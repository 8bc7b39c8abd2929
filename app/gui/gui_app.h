// sph-gui's program: resolves the scene, opens the window, starts the stepper, and runs the main loop
// (shaped like imgui's example_glfw_opengl3: poll, new frame, panels, render, swap).
#pragma once
#include "gui_options.h"

namespace sph::gui {

/// sph-gui's exit codes (those of the headless `sph` where they mean the same).
inline constexpr int kOk = 0, kNoDisplay = 1, kUsage = 2, kInvalidScene = 3, kIoError = 4, kBadLesson = 6;

/// Runs until the window closes (or --quit-after-frames); returns the exit code.
int run_gui(const GuiOptions& options);

}  // namespace sph::gui
