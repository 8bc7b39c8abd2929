// Same input, same result, whatever the thread count (gather loops in a fixed neighbour order).
#include <gtest/gtest.h>
#include <omp.h>

#include "test_util.h"

namespace sph {
namespace {

/// Runs `steps` steps of a scene with its own parameters overridden; thread teams start at 4096
/// particles (engine/src/core/parallel.h), so the scenes here are larger than that.
std::uint64_t run_hash(const std::string& scene, const std::string& key, const std::string& value, int threads,
                       int steps) {
  omp_set_num_threads(threads);
  RunConfig cfg = RunConfig::from_scene(scene);
  cfg.set(key, value, "determinism_test");
  World w(cfg);
  w.set_adaptive_threads(false);  // every step on `threads` threads (not the faster team of World::step)
  for (int s = 0; s < steps; ++s) w.step();
  return test::state_hash(w.particles());
}

/// As run_hash, with two parameters set.
std::uint64_t run_hash2(const std::string& scene, const std::string& k1, const std::string& v1, const std::string& k2,
                        const std::string& v2, int threads, int steps) {
  omp_set_num_threads(threads);
  RunConfig cfg = RunConfig::from_scene(scene);
  cfg.set(k1, v1, "determinism_test");
  cfg.set(k2, v2, "determinism_test");
  World w(cfg);
  w.set_adaptive_threads(false);
  for (int s = 0; s < steps; ++s) w.step();
  return test::state_hash(w.particles());
}

TEST(Determinism, ViscositySwitchIsBitwiseIdenticalWithOneAndTwoThreads) {
  // alpha per particle (a stage of its own, shared with the ghosts) past the reordering at step 16
  for (const char* sw : {"cullen_dehnen", "balsara"}) {
    const std::uint64_t one = run_hash2("gresho", "scene.n_side", "72", "visc.switch", sw, 1, 20);
    const std::uint64_t two = run_hash2("gresho", "scene.n_side", "72", "visc.switch", sw, 2, 20);
    EXPECT_EQ(one, two) << sw;
  }
  omp_set_num_threads(omp_get_num_procs());
}

TEST(Determinism, BitwiseIdenticalWithOneAndTwoThreads) {
  struct Case { const char* scene; const char* key; const char* value; int steps; };
  // 20 steps and more: the particles are reordered at step 16 (and the dam break's Verlet lists rebuilt)
  for (const Case& c : {Case{"box_random", "scene.count", "6000", 20}, Case{"sod", "scene.n_left", "4000", 40},
                        Case{"tube2d", "scene.n_side", "64", 10},
                        // a 2D liquid: 3200 fluid + 1164 dummy wall particles, corrected gradients, walls
                        Case{"dam_break", "scene.dx", "0.025", 20},
                        // DFSPH's pressure solves: Jacobi iterations over the pairs, walls at the fluid's pressure
                        Case{"dam_break_dfsph", "scene.dx", "0.025", 20}, Case{"hydrostatic_tank_dfsph", "scene.dx", "0.02", 20},
                        // self-gravity: a Barnes-Hut tree alone, and SPH with the tree
                        Case{"dust_sphere", "scene.n", "5000", 20}, Case{"evrard", "scene.n", "5000", 17},
                        // two relaxed stars of 2100 (relaxed once, serially: below the thread-team size)
                        Case{"colliding_polytropes", "scene.n", "2100", 20},
                        // the finite pointset method (MLS fits and the re-interpolation onto Gamma_0)
                        Case{"burgers_viscous", "scene.n", "6000", 20}, Case{"burgers_upwind", "scene.n", "6000", 20}}) {
    const std::uint64_t one = run_hash(c.scene, c.key, c.value, 1, c.steps);
    const std::uint64_t two = run_hash(c.scene, c.key, c.value, 2, c.steps);
    EXPECT_EQ(one, two) << c.scene;
    EXPECT_EQ(run_hash(c.scene, c.key, c.value, 2, c.steps), two) << c.scene << " (repeat)";
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace
}  // namespace sph
