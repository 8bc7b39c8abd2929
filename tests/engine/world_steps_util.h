// Shared checks of stepped worlds for the tests: the same state on one and two threads, and a state
// saved part way that resumes bit for bit.
#pragma once
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "sph/config.h"
#include "sph/world.h"

namespace sph::test {

/// `steps` steps of cfg on one and on two threads (no team probe) give the same saved state.
inline void expect_same_steps_on_one_and_two_threads(const RunConfig& cfg, int steps) {
  const int saved = omp_get_max_threads();
  std::string states[2];
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    World w(cfg);
    w.set_adaptive_threads(false);
    for (int k = 0; k < steps; ++k) w.step();
    states[threads - 1] = w.save_state();
  }
  omp_set_num_threads(saved);
  EXPECT_TRUE(states[0] == states[1]) << "the states differ between one and two threads";
}

/// A state saved after `first` steps, restored and stepped to `total`, is the uninterrupted run's.
inline void expect_resume_bitwise(const RunConfig& cfg, int first, int total) {
  World whole(cfg), part(cfg);
  for (int k = 0; k < total; ++k) whole.step();
  for (int k = 0; k < first; ++k) part.step();
  const std::string saved = part.save_state();
  World resumed(cfg);
  resumed.restore_state(saved, "test");
  EXPECT_EQ(resumed.save_state(), saved);
  for (int k = first; k < total; ++k) resumed.step();
  EXPECT_EQ(resumed.time(), whole.time());
  EXPECT_TRUE(resumed.save_state() == whole.save_state()) << "the states differ after the restore";
  EXPECT_EQ(resumed.report().diagnostics().E_tot, whole.report().diagnostics().E_tot);
}

}  // namespace sph::test
