// Cost of a step against problem size (tests/bench/README.md): for each N, build SCENE with KEY = N, take a few warm-up
// steps, then time STEPS steps on THREADS threads and report ns per particle-step (wall, and CPU time of
// all threads, which a busy machine does not inflate), neighbours per particle (list entries and inside
// the support), bytes per particle, the density solve's iterations, ns per neighbour-evaluation of the
// density sum (per neighbour inside the support, per h iteration) and of the force loop (per neighbour),
// and ns per list entry for every part of the evaluation. The
// per-neighbour figures compare with calibration_bench's "ns per neighbour"; "builds" is the share of
// evaluations that built new neighbour lists (the others reuse them), "redo" the share whose density
// solve found an h beyond its list and ran again. "rows/p" counts the rows the loops evaluate (fluid
// and dummy wall particles) per fluid particle and "nb all" the neighbours inside the support of every
// such row per fluid particle, so that "ns/nb all" is the step's CPU time per neighbour the loops
// visit whatever the walls' share (a 3D tank's walls are a larger share of its particles than 2D's).
//   step_cost_bench [scene=box_random] [key=scene.count] [sizes=5000,20000,80000,160000] [steps=10]
//                   [threads=1] [KEY=VALUE ...]
// Extra KEY=VALUE arguments are parameter overrides (e.g. kernel.type=gaussian kernel.eta=1.2).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sph/world.h"

namespace {

/// Resident set size of this process now [bytes] (Linux /proc), 0 if unknown.
double rss_bytes() {
  std::ifstream f("/proc/self/statm");
  double pages_total = 0, pages_rss = 0;
  f >> pages_total >> pages_rss;
  return pages_rss * 4096.0;
}

/// CPU time of this process so far, all threads [s]: with one thread the wall time a busy machine
/// does not inflate (the time the process waited for a core is not in it).
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

/// The rows the pair loops evaluate (fluid, and dummy walls when they take part in the sums) and the
/// neighbours inside the support of each (|r_ij| < support h_i, as the density's count), summed.
struct AllRows {
  double rows = 0.0, neighbours = 0.0;
};
AllRows all_rows(const sph::World& w) {
  const sph::Particles& p = w.particles();
  const sph::NeighbourList& nl = w.neighbours().every_list();
  const double support = sph::Kernel(w.params().kernel.type, p.dim()).support();
  const bool walls = w.params().physics.walls == sph::WallType::Dummy;
  const std::size_t rows = walls ? p.size() : p.fluid();
  const auto& h = p[sph::Field::H];
  AllRows out;
  out.rows = static_cast<double>(rows);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::uint32_t j : nl.of(i))
      if ((p.pos(i) - p.pos(j)).norm2() < support * support * h[i] * h[i]) out.neighbours += 1.0;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "box_random";
  const std::string key = argc > 2 ? argv[2] : "scene.count";
  const auto sizes = split(argc > 3 ? argv[3] : "5000,20000,80000,160000", ',');
  const int steps = argc > 4 ? std::stoi(argv[4]) : 10;
  const int threads = argc > 5 ? std::stoi(argv[5]) : 1;
  omp_set_num_threads(threads);
  std::printf("%s, %d thread(s), %d timed steps after 2 warm-up steps\n", scene.c_str(), threads, steps);
  std::printf("%9s %10s %10s %8s %8s %8s %6s %9s %9s %7s %6s %6s %7s %9s  per part: ns per list entry\n", "N",
              "ns/p-step", "cpu ns/ps", "list/p", "nbrs/p", "bytes/p", "h-its", "rho ns/nb", "f ns/nb", "builds", "redo",
              "rows/p", "nb all", "ns/nb all");
  for (const std::string& value : sizes) {
    const double rss0 = rss_bytes();
    sph::RunConfig cfg = sph::RunConfig::from_scene(scene);
    cfg.set(key, value, "step_cost_bench");
    for (int a = 6; a < argc; ++a) {
      const std::string kv = argv[a];
      const auto eq = kv.find('=');
      if (eq == std::string::npos) { std::fprintf(stderr, "step_cost_bench: '%s' is not KEY=VALUE\n", argv[a]); return 2; }
      cfg.set(kv.substr(0, eq), kv.substr(eq + 1), "step_cost_bench");
    }
    sph::World w(cfg);
    w.set_adaptive_threads(false);  // THREADS threads on every step, no team probe
    for (int s = 0; s < 2; ++s) w.step();
    const std::vector<sph::StageTiming> before = w.report().timings();
    const std::int64_t evals0 = w.report().evaluations(), builds0 = w.neighbours().builds(), over0 = w.neighbours().h_overflows();
    const double cpu0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) w.step();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - cpu0;
    const double n = static_cast<double>(w.particles().fluid());
    const double pairs = static_cast<double>(w.neighbours().pairs());
    const double evals = static_cast<double>(w.report().evaluations() - evals0);
    const sph::DensityStats& ds = w.report().density_stats();
    const double nb = ds.mean_neighbours, its = std::max(1.0, ds.mean_iterations);
    const auto& after = w.report().timings();
    double rho_ns = 0.0, force_ns = 0.0;
    for (std::size_t k = 0; k < after.size() && k < before.size(); ++k) {
      const double sec = after[k].seconds - before[k].seconds;
      if (after[k].name.rfind("density", 0) == 0) rho_ns = 1e9 * sec / (evals * n * nb * its);
      if (after[k].name.rfind("forces", 0) == 0) force_ns = 1e9 * sec / (evals * n * nb);
    }
    const AllRows all = all_rows(w);
    std::printf("%9.0f %10.1f %10.1f %8.1f %8.1f %8.0f %6.2f %9.2f %9.2f %7.2f %6.3f %6.2f %7.1f %9.2f ", n,
                1e9 * wall / (n * steps), 1e9 * cpu / (n * steps), pairs / n,
                nb, (rss_bytes() - rss0) / n, ds.mean_iterations, rho_ns, force_ns,
                static_cast<double>(w.neighbours().builds() - builds0) / evals,
                static_cast<double>(w.neighbours().h_overflows() - over0) / evals, all.rows / n, all.neighbours / n,
                1e9 * cpu / (steps * all.neighbours));
    for (std::size_t k = 0; k < after.size() && k < before.size(); ++k) {
      const double sec = after[k].seconds - before[k].seconds;
      std::printf(" %s %.1f;", after[k].name.c_str(), 1e9 * sec / (pairs * evals));
    }
    std::printf("\n");
  }
  return 0;
}
