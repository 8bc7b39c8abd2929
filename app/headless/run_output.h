// The files of `sph run --out DIR`: scene.json, diagnostics.csv, particles_NNNNN.csv, errors.csv,
// warnings.csv.
#pragma once
#include <fstream>
#include <string>
#include <vector>

#include "sph/world.h"

namespace sph::cli {

struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RunOutput {
 public:
  /// Creates DIR (and parents) and writes scene.json; throws IoError naming the path.
  RunOutput(const std::string& dir, const World& world);
  void write_diagnostics(const World& world);  ///< one row of diagnostics.csv
  void write_particles(const World& world);    ///< the next particles_NNNNN.csv (+ a row of errors.csv)
  /// warnings.csv: what the run tolerated (kind, first step and time, particle id, checks, message); a
  /// header only for a clean run.
  void write_warnings(const World& world);
  int particle_files() const { return files_; }

 private:
  std::string dir_;
  std::ofstream diag_, errors_;
  std::vector<Field> columns_;  ///< the fields of the particle files, after id, x and v
  int files_ = 0;
  double valid_until_ = 0.0;  ///< the reference applies up to this time (the "valid" column)
};

}  // namespace sph::cli
