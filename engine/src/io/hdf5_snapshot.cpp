// The SWIFT/GADGET HDF5 layout (SWIFT's examples/*/makeIC.py; GADGET-4's documentation, "Snapshot file
// format"): one file, the header as attributes of /Header, particles by type in /PartTypeN.
#include <cstdint>
#include <stdexcept>

#include "io/export_box.h"
#include "io/hdf5_swift_groups.h"
#include "io/hdf5_util.h"
#include "sph/ic_export.h"

namespace sph {
namespace {

constexpr int kTypes = 6;  // particle types of the layout (0 gas, 1 dark matter / N-body, ...)

void write_header(hid_t file, const World& world, const ExportBox& box, IcFormat format, int type, std::size_t n) {
  h5::Handle header = h5::create_group(file, "Header");
  std::vector<long long> counts(kTypes, 0);
  counts[static_cast<std::size_t>(type)] = static_cast<long long>(n);
  h5::write_attr_ints(header.get(), "NumPart_ThisFile", counts, H5T_STD_U32LE);
  h5::write_attr_ints(header.get(), "NumPart_Total", counts, H5T_STD_U32LE);
  h5::write_attr_ints(header.get(), "NumPart_Total_HighWord", std::vector<long long>(kTypes, 0), H5T_STD_U32LE);
  h5::write_attr(header.get(), "MassTable", std::vector<double>(kTypes, 0.0));  // masses are per particle
  h5::write_attr(header.get(), "Time", world.time());
  h5::write_attr(header.get(), "Redshift", 0.0);
  if (format == IcFormat::Swift) {
    h5::write_attr(header.get(), "BoxSize", std::vector<double>(box.size.begin(), box.size.end()));
  } else {  // GADGET-4: one side (a cube); 0 = no periodic box
    double side = 0.0;
    if (box.periodic)
      for (int k = 0; k < world.particles().dim(); ++k) side = std::max(side, box.size[k]);
    h5::write_attr(header.get(), "BoxSize", side);
  }
  h5::write_attr_int(header.get(), "NumFilesPerSnapshot", 1);
  h5::write_attr_int(header.get(), "Flag_Entropy_ICs", 0);  // InternalEnergy holds u, not an entropy
  h5::write_attr_int(header.get(), "Flag_DoublePrecision", 1);
  h5::write_attr_int(header.get(), "Dimension", world.particles().dim());
}

void write_units(hid_t file, const UnitSystem& u) {
  h5::Handle units = h5::create_group(file, "Units");
  h5::write_attr(units.get(), "Unit length in cgs (U_L)", u.length_cgs);
  h5::write_attr(units.get(), "Unit mass in cgs (U_M)", u.mass_cgs);
  h5::write_attr(units.get(), "Unit time in cgs (U_t)", u.time_cgs);
  h5::write_attr(units.get(), "Unit current in cgs (U_I)", 1.0);
  h5::write_attr(units.get(), "Unit temperature in cgs (U_T)", 1.0);
}

/// This code's own group: the scene file (physics, parameters, scene values), the box and its walls, and
/// how the file's coordinates and smoothing lengths relate to this code's.
void write_sandbox(hid_t file, const World& world, const ExportBox& box, double h_factor, IcFormat format) {
  h5::Handle g = h5::create_group(file, "SPHSandbox");
  const Domain& d = world.domain();
  h5::write_attr(g.get(), "scene_json", world.config().to_json());
  h5::write_attr(g.get(), "format", std::string(to_string(format)));
  h5::write_attr(g.get(), "domain_lo", std::vector<double>(d.lo.begin(), d.lo.end()));
  h5::write_attr(g.get(), "domain_hi", std::vector<double>(d.hi.begin(), d.hi.end()));
  std::vector<long long> bc;
  for (Boundary b : d.bc) bc.push_back(b == Boundary::Open ? 0 : b == Boundary::Periodic ? 1 : 2);
  h5::write_attr_ints(g.get(), "boundaries", bc, H5T_STD_I32LE);
  h5::write_attr(g.get(), "coordinate_shift", std::vector<double>(box.shift.begin(), box.shift.end()));
  h5::write_attr(g.get(), "smoothing_length_factor", h_factor);
  h5::write_attr(g.get(), "spacing", world.report().spacing());
  h5::write_attr(g.get(), "wall_strength", world.report().wall_strength());
  h5::write_attr(g.get(), "step", static_cast<double>(world.steps()));
}

}  // namespace

std::string hdf5_unsupported(const Params& p) {
  if (p.physics.fpm != FpmType::None)
    return "the finite pointset method (seed 002) has no SPH or N-body state for SWIFT or GADGET-4";
  return {};
}

std::string hdf5_snapshot(const World& world, IcFormat format) {
  const std::string why = hdf5_unsupported(world.params());
  if (!why.empty()) throw std::runtime_error(why);
  const Particles& p = world.particles();
  const std::vector<std::uint32_t>& order = world.by_id();
  const std::size_t n = order.size();
  const ExportBox box = export_box(world);
  const bool nbody = is_nbody(world.params());
  const double h_factor = smoothing_length_factor(world.params().kernel.type, p.dim(), format);

  h5::Handle file = h5::create_memory_file();
  write_header(file.get(), world, box, format, nbody ? 1 : 0, n);
  write_units(file.get(), world.config().scene->units);
  {
    h5::Handle hydro = h5::create_group(file.get(), "HydroScheme");
    h5::write_attr(hydro.get(), "Adiabatic index", world.params().gas.gamma);
  }
  write_sandbox(file.get(), world, box, h_factor, format);
  if (format == IcFormat::Swift) {  // not in GADGET-4 files: yt would take them for SWIFT's (see README)
    const KernelMapping km = kernel_mapping(world.params().kernel.type, p.dim(), format);
    write_swift_groups(file.get(), {box.periodic, !nbody, world.params().physics.gravity != GravityType::None, p.dim(),
                                    km.name, km.ratio});
  }

  h5::Handle part = h5::create_group(file.get(), nbody ? "PartType1" : "PartType0");
  std::vector<double> vec(3 * n), scalar(n);
  for (std::size_t r = 0; r < n; ++r)
    for (int k = 0; k < 3; ++k) vec[3 * r + k] = p.x[k][order[r]] + (k < p.dim() ? box.shift[k] : 0.0);
  h5::write_dataset(part.get(), "Coordinates", vec, 3);
  for (std::size_t r = 0; r < n; ++r)
    for (int k = 0; k < 3; ++k) vec[3 * r + k] = p.v[k][order[r]];
  h5::write_dataset(part.get(), "Velocities", vec, 3);
  auto column = [&](Field f, double factor = 1.0) {
    for (std::size_t r = 0; r < n; ++r) scalar[r] = p.has(f) ? factor * p[f][order[r]] : 0.0;
    return scalar;
  };
  h5::write_dataset(part.get(), "Masses", column(Field::Mass), 1);
  std::vector<std::uint64_t> ids(n);
  for (std::size_t r = 0; r < n; ++r) ids[r] = static_cast<std::uint64_t>(p.id[order[r]]) + 1;  // the codes count from 1
  h5::write_dataset(part.get(), "ParticleIDs", ids);
  if (!nbody || p.has(Field::H)) h5::write_dataset(part.get(), "SmoothingLength", column(Field::H, h_factor), 1);
  if (!nbody) {
    h5::write_dataset(part.get(), "InternalEnergy", column(Field::Energy), 1);  // 0 where the scene has no u
    h5::write_dataset(part.get(), "Density", column(Field::Density), 1);
  }
  if (p.fluid() < p.size()) {  // wall particles: this code's own dataset (the targets have no fixed particles)
    std::vector<std::uint8_t> kind(n);
    for (std::size_t r = 0; r < n; ++r) kind[r] = p.kind[order[r]];
    h5::write_dataset(part.get(), "Kind", kind);
  }
  part.reset();
  return h5::file_bytes(file.get());
}

}  // namespace sph
