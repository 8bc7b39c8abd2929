// ParaView's own formats (VTK XML): one .vtu per particle output, binary appended, and the .pvd time
// series that lists them. The functions return the files' bytes; the caller writes them (one seam for
// every output file).
#pragma once
#include <string>
#include <vector>

#include "sph/world.h"

namespace sph {

/// An unstructured grid of the real particles (one vertex cell each, in id order): the positions as
/// Points (Float64, 3 components); point data "velocity" (a 3-vector), "id" (Int64), "kind" (UInt8: 0 fluid,
/// 1 wall) and every allocated field under its key (Float64); the time as field data "TimeValue".
/// Raw appended binary data with UInt64 block headers, in the machine's byte order (declared).
std::string vtu_file(const World& world);

/// One entry of a .pvd collection: simulated time and the .vtu file name (relative to the .pvd).
struct PvdEntry {
  double t = 0.0;
  std::string file;
};

/// The .pvd collection (ParaView opens it as a time series).
std::string pvd_file(const std::vector<PvdEntry>& entries);

}  // namespace sph
