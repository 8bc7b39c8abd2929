// Initial conditions from HDF5 files in the SWIFT/GADGET layout: `sph run FILE.hdf5` (and a scene file
// whose "scene" is such a file). SWIFT's and GADGET-4's example ICs run as gas (PartType0) or as N-body
// particles (PartType1); what this code cannot run is refused with the file and the reason named.
#pragma once
#include <string>

#include "sph/config.h"

namespace sph {

/// Ends in .hdf5, .h5 or .hdf.
bool is_hdf5_path(const std::string& name);

/// A run configuration whose scene places the file's particles. Files written by this code (their
/// /SPHSandbox group) come back with their scene's physics, parameters, box, walls and reference, so the
/// initial state is the one exported. Other files run as an ideal gas (M4, grad-h SPH, Monaghan
/// viscosity; gas.gamma from /HydroScheme "Adiabatic index", else 5/3) in a periodic box [0, BoxSize)
/// (scene.periodic = 0 makes it open), or as point masses under direct or tree gravity with G in the
/// file's /Units (G = 1 without them). Refused with ConfigError: not HDF5, no /Header, several files per snapshot, a
/// cosmological (Redshift > 0) or entropy (Flag_Entropy_ICs) IC, particle types other than 0 or 1 alone,
/// missing or mis-shaped datasets, non-finite or negative masses, energies or smoothing lengths.
RunConfig load_hdf5_ic(const std::string& path);

}  // namespace sph
