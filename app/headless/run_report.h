// What `sph run` prints when a run ends: the summary line (time, steps, particles, speed, threads), the
// reference's values, run B's line in a comparison, and the warnings of what a run tolerated.
#pragma once
#include <optional>

#include "cli_compare.h"
#include "cli_run.h"
#include "sph/world.h"

namespace sph::cli {

/// The run's "warnings" section on stderr: what it tolerated (nothing is printed for a clean run).
void print_warnings(const World& world);

/// The summary on stdout (nothing with --quiet): the run after `wall` seconds, the reference's values at
/// the end, and run B's line when b is the comparison's.
void print_summary(const RunOptions& opt, const RunConfig& cfg, const World& world, const World* b,
                   const std::optional<CompareSetup>& compare, double wall);

}  // namespace sph::cli
