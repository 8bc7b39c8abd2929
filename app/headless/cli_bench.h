// `sph bench [SCENE...]`: the work-precision report. Each scene with a reference runs its convergence
// study (sph/convergence.h) once per kernel x integrator; bench.csv and bench.md list every run (error,
// wall time, particles, steps) and, in the OSMesa build, bench_SCENE.png plots log10 error against log10
// wall time, one curve per kernel/integrator, drawn by the project's renderer.
#pragma once
#include <string>
#include <vector>

namespace sph::cli {

struct BenchOptions {
  std::vector<std::string> scenes;       ///< empty: the default set (README)
  std::string values;                    ///< comma-separated values of each scene's study key (empty: its own)
  std::string kernels;                   ///< comma-separated (empty: M4,M6,wendland_c2 for SPH scenes)
  std::string integrators;               ///< comma-separated (empty: leapfrog,rk4)
  std::vector<std::string> sets;         ///< key=value overrides of every run
  std::string out = "bench";
  int threads = 0;
  std::string size = "1280x720";
  bool quiet = false;
  bool csv_comments = false;      ///< the # line of earlier versions at the head of the CSV (its text is in the .md)
};

/// The scenes `sph bench` runs when none is named.
const std::vector<std::string>& default_bench_scenes();

int bench_command(const BenchOptions& opt);

}  // namespace sph::cli
