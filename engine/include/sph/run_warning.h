// What a run tolerated without stopping (RunChecks::warnings), shared by the World, the stepper's frames,
// the headless summary and the GUI's status line.
#pragma once
#include <cstdint>
#include <string>

namespace sph {

/// Something a run tolerated: it went on, but its result is degraded or needs care. Kept once per kind
/// (the first time it happened, and how many checks found it since), for the run's summary, the
/// warnings.csv of `sph run --out` and the GUI's status line.
struct RunWarning {
  std::string kind;            ///< "energy", "h_solve", "wall", "domain", "reference", "timestep"
  std::string message;         ///< one line, naming the parameter to change where there is one
  std::int64_t step = 0;       ///< the step it was first found at
  double t = 0.0;              ///< and its time
  std::int64_t particle = -1;  ///< the id of the (first) particle concerned, -1 when it is no single particle's
  std::int64_t times = 1;      ///< how many checks have found it
};

}  // namespace sph
