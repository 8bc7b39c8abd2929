// Initial conditions for the codes that run at scale: the HDF5 layout SWIFT and GADGET-4 read
// (/Header, /Units, /PartType0 gas, /PartType1 N-body particles) and the parameter file each needs,
// with this code's kernel and h mapped to theirs (README "Initial conditions for SWIFT and GADGET-4").
#pragma once
#include <string>
#include <vector>

#include "sph/world.h"

namespace sph {

enum class IcFormat { Swift, Gadget4 };
const char* to_string(IcFormat f);
bool parse(const std::string& s, IcFormat& out);

/// How a kernel of this code maps to the target code's compile-time choice.
struct KernelMapping {
  std::string name;      ///< SWIFT: --with-kernel=NAME; GADGET-4: the Config.sh option
  bool exact = true;     ///< the same function (false: the nearest the target has; see note)
  double ratio = 0.0;    ///< SWIFT: H/h of that kernel in this dimension (Dehnen & Aly 2012, Table 1)
  std::string note;      ///< why it is not exact
};
KernelMapping kernel_mapping(KernelType k, int dim, IcFormat f);

/// SmoothingLength in the file = this factor times this code's h: SWIFT's h is H/gamma_K (H the support
/// radius, gamma_K the kernel's H/h), GADGET-4's is H itself.
double smoothing_length_factor(KernelType k, int dim, IcFormat f);

/// The target's Courant factor (SWIFT's SPH:CFL_condition, GADGET-4's CourantFac) for this code's
/// time.cfl: (3/4) cfl / support, the largest whose step is nowhere longer than this code's (the three
/// step formulas are in io/ic_mapping.cpp).
double courant_factor(double cfl, KernelType k, int dim);

/// The command line that runs the exported SWIFT parameter file (flags from the scene's stages).
std::string swift_run_line(const Params& p, const std::string& param_file);

/// Why the scene cannot be written in this layout ("" when it can): the finite pointset method has no
/// SPH or N-body state.
std::string hdf5_unsupported(const Params& p);

/// The state now as an HDF5 file of the layout, as bytes (built in memory): /Header (NumPart_ThisFile,
/// NumPart_Total, NumPart_Total_HighWord, MassTable, Time, Redshift, BoxSize, NumFilesPerSnapshot,
/// Flag_Entropy_ICs, Flag_DoublePrecision, Dimension), /Units (cgs), /HydroScheme (adiabatic index),
/// /PartType0 (gas: Coordinates, Velocities, Masses, SmoothingLength, InternalEnergy, Density,
/// ParticleIDs) or /PartType1 (N-body: Coordinates, Velocities, Masses, ParticleIDs), and /SPHSandbox
/// (this code's scene, box and walls, so `sph run FILE` restores the same state); SWIFT files also carry
/// SWIFT's snapshot metadata (/Header Code, /RuntimePars, /Policy, ...: yt opens them with their units).
/// Coordinates are shifted into [0, BoxSize) (open axes: one box per run, io/export_box.h). Throws
/// std::runtime_error if hdf5_unsupported() says why not.
std::string hdf5_snapshot(const World& world, IcFormat format);

/// The target code's parameter file for running `ic_file` (SWIFT: YAML with the ./configure line it
/// needs in its head; GADGET-4: param.txt with the Config.sh options in its head). Appends to *warnings
/// what the target cannot reproduce (walls, kernels it lacks, an adiabatic index it cannot compile).
std::string parameter_file(const World& world, IcFormat format, const std::string& ic_file,
                           std::vector<std::string>* warnings);

}  // namespace sph
