// The scripted input of sph-gui's tests (--tap-keys, --click-particle, --push-drag, --scrub-back): key
// taps, mouse clicks and drags on particles, and a look back over the stored frames, at given frames.
#pragma once
#include "gui_options.h"
#include "gui_state.h"
#include "particle_view.h"
#include "window.h"

namespace sph::gui {

/// --tap-keys FRAME:KEYS: the keys tapped through the window's key callback at displayed frame FRAME
/// (+ and - are Ctrl+= and Ctrl+-).
void tap_keys_hook(const GuiOptions& o, long long frame, Window& window);

/// --click-particle FRAME:ID: the mouse on particle ID's dot, pressed at FRAME, released at the next frame
/// (ImGui's input for this frame, after the GLFW backend filled it).
void click_hook(const GuiOptions& o, long long frame, const ParticleView& view, const Rect& r);

/// --push-drag F0:F1:X0,Y0:X1,Y1: the right button held from displayed frame F0 to F1 while the mouse moves
/// evenly from world point (X0, Y0) to (X1, Y1) [length], released at F1.
void push_drag_hook(const GuiOptions& o, long long frame, const ParticleView& view, const Rect& r);

/// --scrub-back N: once the run is at its end (f, the newest frame), the view scrubs back N stored frames.
void scrub_back_hook(const GuiOptions& o, const StepperFrame* f, GuiState& state);

}  // namespace sph::gui
