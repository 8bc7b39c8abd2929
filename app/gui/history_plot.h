// The stepper's diagnostics history resampled at evenly spaced times, so ImGui::PlotLines (which
// spaces its points evenly) draws a true curve against simulated time.
#pragma once
#include <vector>

#include "sph/stepper.h"

namespace sph::gui {

/// `field` of the history at n times evenly spaced over [first t, last t] (linear interpolation).
std::vector<float> resample(const std::vector<HistorySample>& history, double HistorySample::*field, int n);

}  // namespace sph::gui
