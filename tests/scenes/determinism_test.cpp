// Same input, same result, whatever the thread count (gather loops in a fixed neighbour order).
#include <gtest/gtest.h>
#include <omp.h>

#include "test_util.h"

namespace sph {
namespace {

std::uint64_t run_hash(const std::string& scene, int threads, int steps) {
  omp_set_num_threads(threads);
  World w(RunConfig::from_scene(scene));
  for (int s = 0; s < steps; ++s) w.step();
  return test::state_hash(w.particles());
}

TEST(Determinism, BitwiseIdenticalWithOneAndTwoThreads) {
  for (const char* scene : {"box_random", "sod", "tube2d"}) {
    const std::uint64_t one = run_hash(scene, 1, 60);
    const std::uint64_t two = run_hash(scene, 2, 60);
    EXPECT_EQ(one, two) << scene;
    EXPECT_EQ(run_hash(scene, 2, 60), two) << scene << " (repeat)";
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace
}  // namespace sph
