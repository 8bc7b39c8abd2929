// The contents of an initial-condition file in the SWIFT/GADGET HDF5 layout, read and checked: the
// particles in this code's conventions and the header values a scene needs. Reading only; the scene
// that places these particles is built in engine/scenes/hdf5_scene.cpp (load_hdf5_ic, sph/hdf5_ic.h).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/domain.h"
#include "sph/scene.h"

namespace sph {

/// The header values of a file written by another code (SWIFT, GADGET).
struct IcForeignHeader {
  bool periodic = false;   ///< BoxSize > 0, unless /RuntimePars PeriodicBoundariesOn = 0
  bool has_units = false;  ///< a /Units group (else code units)
  UnitSystem units;        ///< from /Units (code units without it)
  bool swift = false;      ///< SWIFT's smoothing-length convention (/Units or a Dimension attribute)
  std::optional<double> adiabatic_index;  ///< /HydroScheme "Adiabatic index" (gas files only)
};

/// The particles of the file in this code's units and conventions (rows in file order).
struct IcData {
  int dim = 3;
  std::size_t n = 0;
  std::vector<double> x, v;  ///< n x 3
  std::vector<double> m, h, u, rho;
  std::vector<std::int64_t> ids;
  std::vector<std::uint8_t> kind;
  std::array<double, 3> box{0, 0, 0};  ///< BoxSize per axis (0: none)
  Domain domain;                       ///< this code's box when the file is this code's own
  bool own = false;                    ///< written by this code (/SPHSandbox)
  double spacing = 0.0, wall_strength = 0.0;
};

/// A whole file: its particle type (0 gas, 1 N-body), particles and header.
struct IcFile {
  int type = 0;
  IcData data;
  RunConfig exported;       ///< data.own: the exported scene, params and scene values (/SPHSandbox scene_json)
  IcForeignHeader foreign;  ///< otherwise: the header of the other code's file
  std::string absolute_path;
};

/// Reads and checks `path`; ConfigError prefixed with the path for whatever sph/hdf5_ic.h refuses.
IcFile read_hdf5_ic(const std::string& path);

/// "%g": the numbers of the messages and descriptions about a file.
std::string ic_text(double v);

}  // namespace sph
