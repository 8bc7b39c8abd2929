// The files of `sph run --out DIR`: scene.json, diagnostics.csv, particles_NNNNN.csv, errors.csv,
// warnings.csv, csv_meta.json (what the CSVs' comment lines said: plain CSVs open as they are), and at
// each particle output, on request, particles_NNNNN.vtu with particles.pvd (ParaView),
// particles_NNNNN.dat (SPLASH) and particles_NNNNN.hdf5 (the SWIFT/GADGET layout).
// Every whole file is written atomically (sph/atomic_file.h) and listed in manifest.json once complete;
// diagnostics.csv and errors.csv grow during the run as NAME.part and are renamed when it ends.
#pragma once
#include <string>
#include <vector>

#include "sph/atomic_file.h"
#include "sph/diverged.h"
#include "sph/output_manifest.h"
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
  bool probe_rows = false;    ///< --probe-every: errors.csv rows come from write_errors, not with the particles
};

/// Where a run's output stood at a checkpoint: enough to continue its files as if it had not stopped.
struct OutputResume {
  int files = 0;                     ///< particle files written
  std::vector<PvdEntry> series;      ///< their times and stems
  std::vector<std::int64_t> steps;   ///< and steps
  FileStamp diag;                    ///< length and CRC-32 of diagnostics.csv (growing as .part)
  FileStamp errors;                  ///< the same of errors.csv (0 bytes without a reference)
  std::vector<ManifestEntry> manifest;  ///< the files manifest.json listed as complete
};

/// Writes `bytes` to path as a whole file (atomically, sph/atomic_file.h); throws IoError naming it.
void write_file(const std::string& path, const std::string& bytes);


class RunOutput {
 public:
  /// Creates DIR (and parents) and writes scene.json; throws IoError naming the path.
  RunOutput(const std::string& dir, const World& world, const OutputOptions& options = {});
  /// Continues the files of a run stopped at a checkpoint: diagnostics.csv and errors.csv (NAME.part, or
  /// NAME if the stopped run finished them) are cut back to their length then (rows written after it go)
  /// and appended to; manifest.json lists what it listed then (run_output_resume.cpp).
  RunOutput(const std::string& dir, const World& world, const OutputOptions& options, const OutputResume& resume);
  /// Where the output stands now (the growing CSVs are flushed first), for a checkpoint.
  OutputResume resume_state();
  /// Unless finish() ran: after an I/O error the .part files are removed, else (a run stopped by a
  /// divergence or a signal) they are finished as far as they got.
  ~RunOutput();
  void write_diagnostics(const World& world);  ///< one row of diagnostics.csv
  /// The next particles_NNNNN.csv (+ a row of errors.csv), and the formats asked for.
  void write_particles(const World& world);
  /// One row of errors.csv now (a run with a reference; nothing otherwise).
  void write_errors(const World& world);
  /// warnings.csv: what the run tolerated (kind, first step and time, particle id, checks, message); a
  /// header only for a clean run. A run stopped by a divergence ends it with a row of kind "diverged"
  /// (its step, time, particle and message), so its folder records why its files end early.
  void write_warnings(const World& world, const DivergedError* stop = nullptr);
  /// Renames diagnostics.csv.part and errors.csv.part to their names and lists them in manifest.json;
  /// throws IoError naming the file.
  void finish();
  int particle_files() const { return files_; }

 private:
  void write_meta(const World& world);
  void put(const std::string& name, const std::string& bytes);  ///< DIR/name, atomically, into the manifest
  void check(const std::string& err);                           ///< throws IoError(err) when err is set
  /// The fields of the particle files after id, x and v.
  static std::vector<Field> particle_columns(const World& world);

  std::string dir_;
  OutputOptions options_;
  OutputManifest manifest_;
  GrowingFile diag_, errors_;
  bool failed_ = false, finished_ = false;
  std::vector<Field> columns_;  ///< the fields of the particle files, after id, x and v
  int files_ = 0;
  double valid_until_ = 0.0;  ///< the reference applies up to this time (the "valid" column)
  std::vector<PvdEntry> series_;  ///< every particle output: time and file stem
  std::vector<std::int64_t> steps_;
};

}  // namespace sph::cli
