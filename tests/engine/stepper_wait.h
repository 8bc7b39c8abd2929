// Waiting on the threaded stepper in tests (sph/stepper.h): poll its latest frame until a condition holds.
#pragma once
#include <chrono>
#include <functional>
#include <thread>

#include "sph/stepper.h"

namespace sph::test {

/// Whether `pred` held for a frame of `s` within `timeout` (polled every 200 us).
inline bool wait_for(Stepper& s, const std::function<bool(const StepperFrame&)>& pred,
                     std::chrono::milliseconds timeout = std::chrono::milliseconds(20000)) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    const StepperFrame* f = s.latest();
    if (f && pred(*f)) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

}  // namespace sph::test
