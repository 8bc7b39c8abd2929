// What `sph run` prints when a run ends: the summary line (time, steps, particles, speed, threads), the
// reference's values, run B's line in a comparison, the warnings of what a run tolerated, and the exit code
// of an energy that drifted.
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

/// kInaccurate after a message when a gravity scene's energy drifted beyond its bound in run A, run B or
/// (sweep_beyond) a sweep's run (the warning names it), else kOk.
int energy_code(const RunConfig& cfg, const World& world, const World* b, bool sweep_beyond = false);

}  // namespace sph::cli
