// Reading initial conditions in the SWIFT/GADGET HDF5 layout (see sph/hdf5_ic.h for what is accepted):
// the datasets and attributes, checked, into an IcFile (io/hdf5_ic_file.h).
#include "io/hdf5_ic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "io/hdf5_util.h"
#include "sph/hdf5_ic.h"

namespace sph {
namespace {

/// Reads a per-particle dataset of `cols` columns (1 or 3); "" check of shape against n.
std::vector<double> column(hid_t group, const char* name, std::size_t n, std::size_t cols) {
  h5::Table t = h5::read_table(group, name);
  if (t.rows != n)
    throw ConfigError(std::string(name) + " has " + std::to_string(t.rows) + " rows for " + std::to_string(n) +
                      " particles");
  if (cols == 1 && t.cols != 1) throw ConfigError(std::string(name) + " must have one value per particle");
  if (cols == 3) {
    if (t.cols < 1 || t.cols > 3) throw ConfigError(std::string(name) + " must have 1 to 3 columns");
    std::vector<double> out(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < t.cols; ++k) out[3 * i + k] = t.values[t.cols * i + k];
    return out;
  }
  return t.values;
}

void check_values(const std::vector<double>& v, const char* name, bool positive) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || v[i] < 0.0 || (positive && v[i] == 0.0))
      throw ConfigError(std::string(name) + " of particle " + std::to_string(i) + " is " + ic_text(v[i]) +
                        " (must be " + (positive ? "positive" : "finite and >= 0") + ")");
}

int particle_type(hid_t header, std::size_t* count) {
  if (!h5::has_attr(header, "NumPart_ThisFile")) throw ConfigError("/Header has no NumPart_ThisFile");
  const std::vector<double> counts = h5::read_attr(header, "NumPart_ThisFile");
  if (h5::has_attr(header, "NumFilesPerSnapshot")) {
    const std::vector<double> files = h5::read_attr(header, "NumFilesPerSnapshot");
    if (!files.empty() && files[0] > 1)
      throw ConfigError("the snapshot is split over " + ic_text(files[0]) + " files (NumFilesPerSnapshot): join them first");
  }
  int type = -1;
  std::string present;
  for (std::size_t t = 0; t < counts.size(); ++t) {
    if (counts[t] <= 0) continue;
    present += " PartType" + std::to_string(t) + " (" + ic_text(counts[t]) + ")";
    if (type >= 0 || t > 1) type = -2;
    else type = static_cast<int>(t);
  }
  if (type == -1) throw ConfigError("NumPart_ThisFile counts no particles");
  if (type == -2)
    throw ConfigError("particles of" + present +
                      ": this code runs gas (PartType0) alone or N-body particles (PartType1) alone");
  *count = static_cast<std::size_t>(counts[static_cast<std::size_t>(type)]);
  return type;
}

void refuse_unsupported_header(hid_t header) {
  if (h5::has_attr(header, "Flag_Entropy_ICs")) {
    for (double f : h5::read_attr(header, "Flag_Entropy_ICs"))
      if (f != 0.0)
        throw ConfigError("Flag_Entropy_ICs = 1: InternalEnergy holds an entropy A = P/rho^gamma; this code starts "
                          "from the specific internal energy u (write u and set the flag to 0)");
  }
  if (h5::has_attr(header, "Redshift")) {
    const std::vector<double> z = h5::read_attr(header, "Redshift");
    if (!z.empty() && z[0] > 0.0)
      throw ConfigError("Redshift = " + ic_text(z[0]) +
                        ": a cosmological IC needs comoving integration, which this code does not have");
  }
}

UnitSystem read_units(hid_t file, const std::string& path) {
  UnitSystem u;
  h5::Handle g = h5::open_group(file, "Units");
  if (!g.valid()) return u;
  auto get = [&](const char* name, double fallback) {
    if (!h5::has_attr(g.get(), name)) return fallback;
    const std::vector<double> v = h5::read_attr(g.get(), name);
    return v.empty() ? fallback : v[0];
  };
  u.length_cgs = get("Unit length in cgs (U_L)", 1.0);
  u.mass_cgs = get("Unit mass in cgs (U_M)", 1.0);
  u.time_cgs = get("Unit time in cgs (U_t)", 1.0);
  u.name = "U_L = " + ic_text(u.length_cgs) + " cm, U_M = " + ic_text(u.mass_cgs) + " g, U_t = " + ic_text(u.time_cgs) +
           " s (/Units of " + std::filesystem::path(path).filename().string() + ")";
  return u;
}

/// Ids 0..n-1 in the order of the file's ParticleIDs (ties and absent ids: file order).
std::vector<std::int64_t> dense_ids(const std::vector<std::int64_t>& file_ids, std::size_t n) {
  std::vector<std::int64_t> ids(n);
  if (file_ids.size() != n) {
    std::iota(ids.begin(), ids.end(), std::int64_t{0});
    return ids;
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return file_ids[a] < file_ids[b]; });
  for (std::size_t r = 0; r < n; ++r) ids[order[r]] = static_cast<std::int64_t>(r);
  return ids;
}

IcData read_particles(hid_t file, int type, std::size_t n) {
  IcData d;
  d.n = n;
  const std::string name = "PartType" + std::to_string(type);
  h5::Handle g = h5::open_group(file, name.c_str());
  if (!g.valid()) throw ConfigError("no /" + name + " group for its " + std::to_string(n) + " particles");
  auto need = [&](const char* ds) {
    if (!h5::exists(g.get(), ds)) throw ConfigError("/" + name + "/" + ds + " is missing");
  };
  need("Coordinates");
  need("Velocities");
  d.x = column(g.get(), "Coordinates", n, 3);
  d.v = column(g.get(), "Velocities", n, 3);
  for (double c : d.x)
    if (!std::isfinite(c)) throw ConfigError("/" + name + "/Coordinates has a non-finite value");
  for (double c : d.v)
    if (!std::isfinite(c)) throw ConfigError("/" + name + "/Velocities has a non-finite value");
  if (h5::exists(g.get(), "Masses")) {
    d.m = column(g.get(), "Masses", n, 1);
  } else {
    h5::Handle header = h5::open_group(file, "Header");
    const std::vector<double> table =
        h5::has_attr(header.get(), "MassTable") ? h5::read_attr(header.get(), "MassTable") : std::vector<double>{};
    if (static_cast<std::size_t>(type) >= table.size() || !(table[static_cast<std::size_t>(type)] > 0.0))
      throw ConfigError("/" + name + "/Masses is missing and MassTable gives no mass for type " + std::to_string(type));
    d.m.assign(n, table[static_cast<std::size_t>(type)]);
  }
  check_values(d.m, "Masses", true);
  if (type == 0) {
    need("InternalEnergy");
    d.u = column(g.get(), "InternalEnergy", n, 1);
    check_values(d.u, "InternalEnergy", false);
  }
  if (h5::exists(g.get(), "SmoothingLength")) {
    d.h = column(g.get(), "SmoothingLength", n, 1);
    check_values(d.h, "SmoothingLength", false);
  }
  if (h5::exists(g.get(), "Density")) d.rho = column(g.get(), "Density", n, 1);
  d.ids = dense_ids(h5::exists(g.get(), "ParticleIDs") ? h5::read_ints(g.get(), "ParticleIDs") : std::vector<std::int64_t>{},
                    n);
  if (h5::exists(g.get(), "Kind")) {
    const std::vector<double> k = column(g.get(), "Kind", n, 1);
    for (double v : k) d.kind.push_back(v == 1.0 ? 1 : 0);
  }
  return d;
}

/// The dimension: /Header Dimension, else 3 unless every z (and y) is zero (a GADGET TWODIMS/ONEDIMS IC).
int read_dimension(hid_t header, const IcData& d) {
  if (h5::has_attr(header, "Dimension")) {
    const std::vector<double> v = h5::read_attr(header, "Dimension");
    if (v.empty() || !(v[0] == 1 || v[0] == 2 || v[0] == 3))
      throw ConfigError("Dimension must be 1, 2 or 3, not " + (v.empty() ? std::string("empty") : ic_text(v[0])));
    const int dim = static_cast<int>(v[0]);
    for (std::size_t i = 0; i < d.n; ++i)
      for (int k = dim; k < 3; ++k)
        if (d.x[3 * i + k] != 0.0)
          throw ConfigError("Dimension = " + std::to_string(dim) + " but particle " + std::to_string(i) + " has " +
                            "xyz"[k] + " = " + ic_text(d.x[3 * i + k]));
    return dim;
  }
  auto all_zero = [&](int k) {
    for (std::size_t i = 0; i < d.n; ++i)
      if (d.x[3 * i + k] != 0.0) return false;
    return true;
  };
  return all_zero(2) ? (all_zero(1) ? 1 : 2) : 3;
}

/// This code's own export: the scene it came from and the box, walls and conventions of /SPHSandbox.
void read_own(hid_t file, IcFile& f, const std::string& path) {
  IcData& d = f.data;
  h5::Handle g = h5::open_group(file, "SPHSandbox");
  f.exported = RunConfig::from_json_text(h5::read_attr_string(g.get(), "scene_json"), path + " (/SPHSandbox)");
  const std::vector<double> lo = h5::read_attr(g.get(), "domain_lo"), hi = h5::read_attr(g.get(), "domain_hi"),
                            bc = h5::read_attr(g.get(), "boundaries"), shift = h5::read_attr(g.get(), "coordinate_shift");
  if (lo.size() != 3 || hi.size() != 3 || bc.size() != 3 || shift.size() != 3)
    throw ConfigError("/SPHSandbox: domain_lo, domain_hi, boundaries and coordinate_shift need three values each");
  const double h_factor = h5::read_attr(g.get(), "smoothing_length_factor").at(0);
  d.own = true;
  d.spacing = h5::read_attr(g.get(), "spacing").at(0);
  if (h5::has_attr(g.get(), "wall_strength")) d.wall_strength = h5::read_attr(g.get(), "wall_strength").at(0);
  for (int k = 0; k < 3; ++k) {
    d.domain.lo[k] = lo[k];
    d.domain.hi[k] = hi[k];
    d.domain.bc[k] = bc[k] == 1 ? Boundary::Periodic : bc[k] == 2 ? Boundary::Wall : Boundary::Open;
  }
  d.dim = f.exported.scene->dim;
  for (std::size_t i = 0; i < d.n; ++i)
    for (int k = 0; k < d.dim; ++k) d.x[3 * i + k] -= shift[k];
  if (!d.h.empty() && h_factor > 0.0)
    for (double& h : d.h) h /= h_factor;
}

/// Another code's file: dimension, box, periodicity, units and adiabatic index from its header groups.
void read_foreign(hid_t file, hid_t header, IcFile& f, const std::string& path) {
  IcData& d = f.data;
  IcForeignHeader& fh = f.foreign;
  d.dim = read_dimension(header, d);
  if (h5::has_attr(header, "BoxSize")) {
    const std::vector<double> b = h5::read_attr(header, "BoxSize");
    for (int k = 0; k < 3; ++k) d.box[k] = b.empty() ? 0.0 : b[b.size() == 3 ? static_cast<std::size_t>(k) : 0];
  }
  fh.periodic = d.box[0] > 0.0;
  if (h5::Handle rp = h5::open_group(file, "RuntimePars"); rp.valid() && h5::has_attr(rp.get(), "PeriodicBoundariesOn"))
    fh.periodic = fh.periodic && h5::read_attr(rp.get(), "PeriodicBoundariesOn").at(0) != 0.0;
  fh.units = read_units(file, path);
  fh.has_units = h5::exists(file, "Units");
  if (f.type == 0) {
    if (h5::Handle hs = h5::open_group(file, "HydroScheme"); hs.valid() && h5::has_attr(hs.get(), "Adiabatic index"))
      fh.adiabatic_index = h5::read_attr(hs.get(), "Adiabatic index").at(0);
  }
  fh.swift = fh.has_units || h5::has_attr(header, "Dimension");
}

}  // namespace

std::string ic_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool is_hdf5_path(const std::string& name) {
  return name.ends_with(".hdf5") || name.ends_with(".h5") || name.ends_with(".hdf");
}

IcFile read_hdf5_ic(const std::string& path) {
  // the non-throwing form: a name the system refuses (too long, say) is an input error, not an exception
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw ConfigError(path + (ec ? ": cannot be read (" + ec.message() + ")" : std::string(": no such file")));
  h5::Handle file = h5::open_file(path);
  if (!file.valid()) throw ConfigError(path + ": not an HDF5 file (or it cannot be read)");
  try {
    h5::Handle header = h5::open_group(file.get(), "Header");
    if (!header.valid()) throw ConfigError("no /Header group: not an initial condition in the SWIFT/GADGET layout");
    refuse_unsupported_header(header.get());
    std::size_t n = 0;
    IcFile f;
    f.type = particle_type(header.get(), &n);
    f.data = read_particles(file.get(), f.type, n);
    if (h5::exists(file.get(), "SPHSandbox")) read_own(file.get(), f, path);
    else read_foreign(file.get(), header.get(), f, path);
    f.absolute_path = std::filesystem::absolute(path).string();
    return f;
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    throw ConfigError(msg.starts_with(path) ? msg : path + ": " + msg);
  } catch (const std::exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace sph
