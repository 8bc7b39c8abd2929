// Thread speed-up on a 2D scene (tests/bench/README.md): SCENE with KEY=VALUE (its size), STEPS steps, timed with 1 and
// with N threads; also checks that both runs end in the same state (determinism).
//   scaling_bench [scene=box_random] [key=scene.count] [value=40000] [steps=20] [threads=2] [team=fixed]
// team=fixed: every step on the team asked for (the world's team chooser off), the speed-up of the team
// itself. team=chosen: the world chooses as in sph and sph-gui; its first 8 steps probe one thread and
// then the team (4 steps each), so a short run shows the probe's cost, not the team's speed-up.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "sph/world.h"

namespace {

double run(int threads, bool chosen, const std::string& scene, const std::string& key, const std::string& value,
           int steps, std::uint64_t& checksum, int& team) {
  omp_set_num_threads(threads);
  sph::RunConfig cfg = sph::RunConfig::from_scene(scene);
  cfg.set(key, value, "scaling_bench");
  sph::World w(cfg);
  w.set_adaptive_threads(chosen);
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) w.step();
  team = w.last_team();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  checksum = 0;
  for (double x : w.particles().x[0]) {
    std::uint64_t b;
    static_assert(sizeof b == sizeof x);
    __builtin_memcpy(&b, &x, sizeof b);
    checksum = checksum * 1099511628211ull ^ b;
  }
  return wall;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "box_random";
  const std::string key = argc > 2 ? argv[2] : "scene.count";
  const std::string value = argc > 3 ? argv[3] : "40000";
  const int steps = argc > 4 ? std::stoi(argv[4]) : 20;
  const int threads = argc > 5 ? std::stoi(argv[5]) : 2;
  const std::string team = argc > 6 ? argv[6] : "fixed";
  if (team != "fixed" && team != "chosen") {
    std::fprintf(stderr, "scaling_bench: team must be 'fixed' or 'chosen', not '%s'\n", team.c_str());
    return 2;
  }
  const bool chosen = team == "chosen";
  std::uint64_t c1 = 0, cn = 0;
  int team1 = 0, teamn = 0;
  const double t1 = run(1, chosen, scene, key, value, steps, c1, team1);
  const double tn = run(threads, chosen, scene, key, value, steps, cn, teamn);
  std::printf("%s %s=%s, %d steps: 1 thread %.3f s, %d threads %.3f s (team %s, last: %d), speed-up %.2f, %s\n",
              scene.c_str(), key.c_str(), value.c_str(), steps, t1, threads, tn, team.c_str(), teamn, t1 / tn,
              c1 == cn ? "identical states" : "STATES DIFFER");
  return c1 == cn ? 0 : 1;
}
