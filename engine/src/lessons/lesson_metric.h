// A lesson check's measurement (private to src/lessons): one run of a scene, the metric sampled after
// every step and reduced over the run.
#pragma once
#include <string>

#include "sph/config.h"

namespace sph::lessons {

/// The metric names `cfg`'s scene offers: its reference's columns and the extra metrics, space-separated
/// (messages); `known` is set to whether `metric` is among them. Builds the World (no step).
std::string metric_names(const RunConfig& cfg, const std::string& metric, bool* known);

}  // namespace sph::lessons
