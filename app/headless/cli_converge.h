// `sph converge SCENE`: a convergence study (sph/convergence.h) written as converge.csv, converge.md
// and, in the OSMesa build, converge.png (log10 error against log10 h with the fitted line, drawn by
// the project's renderer).
#pragma once
#include <string>
#include <vector>

namespace sph::cli {

struct ConvergeOptions {
  std::string scene;
  std::vector<std::string> sets;  ///< key=value overrides of every run
  std::string key;                ///< empty: the scene's default
  std::string values;             ///< comma-separated; empty: the scene's default
  double until = -1.0;            ///< comparison time (< 0: the scene's default)
  std::string column;             ///< reference column (empty: the primary error)
  std::string out;                ///< output directory (empty: converge_SCENE)
  int threads = 0;
  std::string size = "1280x720";
  bool quiet = false;
  bool csv_comments = false;      ///< the # line of earlier versions at the head of the CSV (its text is in the .md)
};

int converge_command(const ConvergeOptions& opt);

}  // namespace sph::cli
