// Convergence studies: a scene with a reference run over a list of values of one key (usually its
// resolution), the error of one reference column at a fixed time, and the observed order between
// consecutive runs p = log(e1/e2) / log(h1/h2), h the scene's initial particle spacing (seed 002 §4.3)
// or, for a study of time.dt, the timestep,
// with the least-squares slope of log e against log h over all runs.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sph/config.h"

namespace sph {

struct ConvergenceStudy {
  std::string key;            ///< e.g. "scene.n"; empty: the scene's default study
  std::vector<double> values; ///< empty: the scene's default values
  double t = -1.0;            ///< time of the comparison (< 0: the scene's default, else its t_end)
  std::string column;         ///< reference column (empty: the reference's primary error)
};

struct ConvergenceRun {
  double value = 0.0;   ///< of the key
  double h = 0.0;       ///< initial particle spacing [length] (the timestep for a study of time.dt)
  double error = 0.0;   ///< the column's value at t
  double order = 0.0;   ///< against the previous run (NaN for the first)
  double wall_s = 0.0;  ///< wall time of the run [s]
  std::int64_t steps = 0;
  std::size_t particles = 0;  ///< real particles at the end
  bool valid = true;          ///< the reference still applied at t (Reference::valid_until)
  std::size_t warnings = 0;   ///< kinds of warning the run raised (RunChecks::warnings)
};

struct ConvergenceResult {
  std::string scene, key, column, column_description;
  double t = 0.0;
  std::vector<ConvergenceRun> runs;
  double slope = 0.0;  ///< least-squares d log e / d log h over all runs
  /// What h is, as the outputs name it: "dx" (the initial spacing) or "dt" (a timestep study). Not "h",
  /// which is the smoothing length everywhere else.
  std::string step_name() const { return key == "time.dt" ? "dt" : "dx"; }
  std::string step_meaning() const { return key == "time.dt" ? "the time step" : "the initial spacing"; }
};

/// The study's key, values and time once the scene's defaults are filled in; throws ConfigError when
/// the scene has no reference, the column is unknown, or nothing says what to vary.
ConvergenceStudy resolve_study(const RunConfig& base, const ConvergenceStudy& asked);
/// Runs the (resolved) study from `base`; `progress` is called after each run. Throws ConfigError for
/// a bad value of the key and DivergedError when a run blows up.
ConvergenceResult run_convergence(const RunConfig& base, const ConvergenceStudy& study,
                                  const std::function<void(const ConvergenceRun&)>& progress = {});
/// CSV (a header row, then one row per run; with `comment`, first a # line naming the scene, column and
/// time, as earlier versions wrote) and a markdown table like seed 002's Table 1.
std::string convergence_csv(const ConvergenceResult& r, bool comment = false);
std::string convergence_markdown(const ConvergenceResult& r);

}  // namespace sph
