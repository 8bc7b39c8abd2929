// What the particle view draws from a stepper frame: run A, and run B when comparing, with their
// labels (the overridden keys with each run's values) and reference errors (for the L1 in the legend),
// and the inspected particle with its neighbours (ring strength: W / the largest W among them).
#pragma once
#include "frame_scene.h"
#include "sph/stepper.h"

namespace sph::gui {

/// Points into f (valid while f is).
render::FrameScene view_scene(const StepperFrame& f);

/// The inspector's highlight (run 0 = A): the particle's snapshot index is its id.
render::Highlight highlight_of(const Inspection& in);

}  // namespace sph::gui
