// The files of `sph run --out DIR`: scene.json, diagnostics.csv, particles_NNNNN.csv, errors.csv,
// warnings.csv, csv_meta.json (what the CSVs' comment lines said: plain CSVs open as they are), and at
// each particle output, on request, particles_NNNNN.vtu with particles.pvd (ParaView),
// particles_NNNNN.dat (SPLASH) and particles_NNNNN.hdf5 (the SWIFT/GADGET layout).
#pragma once
#include <fstream>
#include <string>
#include <vector>

#include "sph/vtu_writer.h"
#include "sph/world.h"

namespace sph::cli {

struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What a run writes besides its CSV files.
struct OutputOptions {
  bool csv_comments = false;  ///< the '#' lines of earlier versions in the CSVs (else csv_meta.json holds them)
  bool vtu = false;           ///< --vtu: particles_NNNNN.vtu and the particles.pvd series
  bool splash = false;        ///< --splash: particles_NNNNN.dat for SPLASH's ascii reader
  bool hdf5 = false;          ///< --hdf5: particles_NNNNN.hdf5 in the SWIFT layout
};

/// Where a run's output stood at a checkpoint: enough to continue its files as if it had not stopped.
struct OutputResume {
  int files = 0;                     ///< particle files written
  std::vector<PvdEntry> series;      ///< their times and stems
  std::vector<std::int64_t> steps;   ///< and steps
  std::uint64_t diag_bytes = 0;      ///< length of diagnostics.csv
  std::uint64_t errors_bytes = 0;    ///< length of errors.csv (0 without a reference)
};

/// Writes `bytes` to path as a whole file (through the one atomic-write seam); throws IoError naming it.
void write_file(const std::string& path, const std::string& bytes);

class RunOutput {
 public:
  /// Creates DIR (and parents) and writes scene.json; throws IoError naming the path.
  RunOutput(const std::string& dir, const World& world, const OutputOptions& options = {});
  /// Continues the files of a run stopped at a checkpoint: diagnostics.csv and errors.csv are cut back
  /// to their length then (rows written after it go) and appended to (run_output_resume.cpp).
  RunOutput(const std::string& dir, const World& world, const OutputOptions& options, const OutputResume& resume);
  /// Where the output stands now (the CSV streams are flushed first), for a checkpoint.
  OutputResume resume_state();
  void write_diagnostics(const World& world);  ///< one row of diagnostics.csv
  /// The next particles_NNNNN.csv (+ a row of errors.csv), and the formats asked for.
  void write_particles(const World& world);
  /// warnings.csv: what the run tolerated (kind, first step and time, particle id, checks, message); a
  /// header only for a clean run.
  void write_warnings(const World& world);
  int particle_files() const { return files_; }

 private:
  void write_meta(const World& world) const;
  /// The fields of the particle files after id, x and v.
  static std::vector<Field> particle_columns(const World& world);

  std::string dir_;
  OutputOptions options_;
  std::ofstream diag_, errors_;
  std::vector<Field> columns_;  ///< the fields of the particle files, after id, x and v
  int files_ = 0;
  double valid_until_ = 0.0;  ///< the reference applies up to this time (the "valid" column)
  std::vector<PvdEntry> series_;  ///< every particle output: time and file stem
  std::vector<std::int64_t> steps_;
};

}  // namespace sph::cli
