// Evaluating a lesson step's claim (sph/lesson.h): the runs it needs, headless, with the measured numbers
// in the result's text, e.g. "L1_rho(scene.n_left=400)=0.003044 < L1_rho(scene.n_left=200)=0.005803 / 1.5".
#pragma once
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/lesson.h"

namespace sph {

struct CheckResult {
  bool pass = false;
  std::string text;              ///< the measured values and the comparison made
  std::vector<double> measured;  ///< the reduced metric of each run, in run order
};

/// The configuration of a step's run with extra overrides (after the step's own); throws ConfigError.
RunConfig lesson_config(const LessonStep& step, const LessonSets& extra);
/// Runs the scene of `cfg` to `until` (< 0: its t_end) and reduces the metric over the run (see
/// LessonCheck). Throws LessonError for an unknown metric, DivergedError if the run blows up.
double measure(const RunConfig& cfg, const std::string& metric, const std::string& reduce, double until);
/// Runs a step's check. Throws DivergedError if a run blows up.
CheckResult evaluate_check(const LessonStep& step);
/// Metric names besides the reference's columns: E_drift (|E_tot - E_tot(0)| over |E_kin|+|E_int|+|E_pot|
/// at t = 0), tv_vx (total variation of v_x along x over the fluid particles), updates (particle
/// evaluations so far: with individual time steps, only the active particles') and v_max (the largest
/// fluid particle speed).
std::vector<std::string> extra_metrics();

}  // namespace sph
