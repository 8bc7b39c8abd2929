// The stepper's diagnostics history resampled at evenly spaced times, so ImGui::PlotLines (which
// spaces its points evenly) draws a true curve against simulated time.
#pragma once
#include <vector>

#include "sph/stepper.h"

namespace sph::gui {

/// `field` of the history at n times evenly spaced over [first t, last t] (linear interpolation).
std::vector<float> resample(const std::vector<HistorySample>& history, double HistorySample::*field, int n);
/// Reference column k of the history (HistorySample::ref) at n evenly spaced times.
std::vector<float> resample_ref(const std::vector<HistorySample>& history, std::size_t k, int n);

}  // namespace sph::gui
