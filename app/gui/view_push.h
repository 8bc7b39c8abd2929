// Right-drag on a 2D plane view pushes the fluid under the mouse (push_drag.h, sph/push.h): while the
// right button is held, the engine drags the particles within R of the cursor along with it; the push's
// radius is drawn as a circle under the cursor. Not on profiles, 3D views, A/B comparisons or while
// scrubbing (the view then is not the live run).
#pragma once
#include "gui_state.h"
#include "layout.h"
#include "particle_view.h"

namespace sph::gui {

/// `r`: where the view is drawn [framebuffer px]. Call every display frame after ImGui::NewFrame.
void push_particles(GuiState& s, const ParticleView& view, const Rect& r);

/// Test hook --push-drag: the window position [ImGui's mouse coordinates] of world point (x, y) in the
/// view drawn into `r`, or false before the view is drawn.
bool window_pos_of_world(const ParticleView& view, const Rect& r, double x, double y, float* wx, float* wy);

}  // namespace sph::gui
