// SWIFT's snapshot metadata for files in its layout (see hdf5_swift_groups.cpp): what makes yt open them
// with its SWIFT frontend (units from /Units, box from /Header BoxSize) and tools read the kernel.
#pragma once
#include <hdf5.h>

#include <string>

namespace sph {

struct SwiftGroups {
  bool periodic = false;      ///< RuntimePars PeriodicBoundariesOn (SWIFT: all axes or none)
  bool hydro = true;          ///< gas (PartType0) rather than N-body particles
  bool self_gravity = false;  ///< the scene has self-gravity
  int dim = 3;                ///< the hydro dimension
  std::string kernel_name;    ///< SWIFT's --with-kernel name
  double kernel_gamma = 0.0;  ///< H/h of that kernel in this dimension
};

/// Adds /Header Code, /RuntimePars, /Policy, /Parameters, /SubgridScheme and the kernel attributes of an
/// existing /HydroScheme. /Header must exist already.
void write_swift_groups(hid_t file, const SwiftGroups& s);

}  // namespace sph
