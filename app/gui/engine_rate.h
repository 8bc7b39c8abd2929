// Engine steps per wall second over a whole GUI session, from the frames it displayed (for the exit
// summary; the status line shows the stepper's own short-window rate).
#pragma once
#include <chrono>
#include <cstdint>

#include "sph/stepper.h"

namespace sph::gui {

/// Steps of the current World between the first and the last frame seen, over the wall time between them.
struct EngineRate {
  std::uint64_t world = 0;
  std::int64_t step0 = 0, step1 = 0;
  std::chrono::steady_clock::time_point wall0, wall1;
  bool started = false;
  void see(const StepperFrame& f) {
    const auto now = std::chrono::steady_clock::now();
    if (!started || f.world_serial != world) {
      started = true;
      world = f.world_serial;
      step0 = step1 = f.snapshot.step;
      wall0 = wall1 = now;
    } else if (f.snapshot.step != step1) {
      step1 = f.snapshot.step;
      wall1 = now;
    }
  }
  double rate() const {
    const double s = std::chrono::duration<double>(wall1 - wall0).count();
    return s > 0.0 ? static_cast<double>(step1 - step0) / s : 0.0;
  }
};

}  // namespace sph::gui
