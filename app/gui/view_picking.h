// The mouse on the particle view: hovering a particle shows its id and the value of the coloured field
// in a tooltip; a click (without a drag) opens the particle inspector on it.
#pragma once
#include "gui_state.h"
#include "layout.h"
#include "particle_view.h"

namespace sph::gui {

/// `r`: where the view is drawn [framebuffer px]. Does nothing while ImGui wants the mouse.
void pick_particles(GuiState& s, const ParticleView& view, const Rect& r);

}  // namespace sph::gui
