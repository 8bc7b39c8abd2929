// `sph export-ics SCENE --format swift|gadget4 --out FILE.hdf5`: a scene's initial condition in the
// HDF5 layout SWIFT and GADGET-4 read, and beside it the parameter file each needs (sph/ic_export.h).
#pragma once
#include <string>
#include <vector>

namespace sph::cli {

struct ExportOptions {
  std::string scene;
  std::vector<std::string> sets;  ///< key=value overrides
  double until = -1.0;            ///< time.t_end written to the parameter file (< 0: the scene's)
  std::string format = "swift";   ///< swift or gadget4
  std::string out;                ///< the .hdf5 file; the parameter file is FILE without .hdf5 + .yml / -param.txt
  int threads = 0;
};

int export_command(const ExportOptions& opt);

/// The parameter file's path for an IC path and format: sod.hdf5 -> sod.yml (SWIFT), sod-param.txt (GADGET-4).
std::string parameter_path(const std::string& ic_path, const std::string& format);

}  // namespace sph::cli
