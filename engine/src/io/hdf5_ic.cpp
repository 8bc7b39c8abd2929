// Reading initial conditions in the SWIFT/GADGET HDF5 layout (see sph/hdf5_ic.h for what is accepted).
#include "sph/hdf5_ic.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "core/pipeline.h"
#include "io/hdf5_util.h"
#include "nbody_common.h"
#include "scene_util.h"
#include "sph/ic_export.h"
#include "sph/kernel.h"

namespace sph {
namespace {

constexpr double kGravityCgs = 6.67430e-8;  // CODATA 2018 [cm^3 g^-1 s^-2]

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

std::string text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

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
      throw ConfigError(std::string(name) + " of particle " + std::to_string(i) + " is " + text(v[i]) + " (must be " +
                        (positive ? "positive" : "finite and >= 0") + ")");
}

int particle_type(hid_t header, std::size_t* count) {
  if (!h5::has_attr(header, "NumPart_ThisFile")) throw ConfigError("/Header has no NumPart_ThisFile");
  const std::vector<double> counts = h5::read_attr(header, "NumPart_ThisFile");
  if (h5::has_attr(header, "NumFilesPerSnapshot")) {
    const std::vector<double> files = h5::read_attr(header, "NumFilesPerSnapshot");
    if (!files.empty() && files[0] > 1)
      throw ConfigError("the snapshot is split over " + text(files[0]) + " files (NumFilesPerSnapshot): join them first");
  }
  int type = -1;
  std::string present;
  for (std::size_t t = 0; t < counts.size(); ++t) {
    if (counts[t] <= 0) continue;
    present += " PartType" + std::to_string(t) + " (" + text(counts[t]) + ")";
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
      throw ConfigError("Redshift = " + text(z[0]) + ": a cosmological IC needs comoving integration, which this code "
                        "does not have");
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
  u.name = "U_L = " + text(u.length_cgs) + " cm, U_M = " + text(u.mass_cgs) + " g, U_t = " + text(u.time_cgs) +
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

/// The scene that places the file's particles.
SceneSetup place(const IcData& d, const Params& prm, bool periodic) {
  Particles p(d.dim, d.n, Pipeline(prm.physics, d.dim).fields());
  for (std::size_t i = 0; i < d.n; ++i) {
    for (int k = 0; k < d.dim; ++k) {
      p.x[k][i] = d.x[3 * i + k];
      p.v[k][i] = d.v[3 * i + k];
    }
    p.id[i] = d.ids[i];
    if (!d.kind.empty() && d.kind[i] == static_cast<std::uint8_t>(Kind::Wall)) p.kind[i] = d.kind[i];
    p[Field::Mass][i] = d.m[i];
    p[Field::H][i] = d.h[i];
    if (p.has(Field::Energy) && !d.u.empty()) p[Field::Energy][i] = d.u[i];
    if (p.has(Field::Density) && !d.rho.empty()) p[Field::Density][i] = d.rho[i];
  }
  SceneSetup s{std::move(p), d.domain, d.spacing, d.wall_strength};
  if (!d.own) {  // a foreign file: its box, periodic or open
    for (int k = 0; k < 3; ++k) {
      s.domain.bc[k] = Boundary::Open;
      s.domain.lo[k] = 0.0;
      s.domain.hi[k] = d.box[k] > 0.0 ? d.box[k] : 1.0;
    }
    if (periodic) {
      for (int k = 0; k < d.dim; ++k) {
        if (!(d.box[k] > 0.0))
          throw ConfigError("scene.periodic = 1 needs a BoxSize > 0 on every axis of the IC (axis " +
                            std::string(1, "xyz"[k]) + " has " + text(d.box[k]) + ")");
        s.domain.bc[k] = Boundary::Periodic;
      }
      if (prm.physics.gravity != GravityType::None)
        throw ConfigError("self-gravity needs an open box: set scene.periodic = 0");
    }
  }
  return s;
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
      throw ConfigError("Dimension must be 1, 2 or 3, not " + (v.empty() ? std::string("empty") : text(v[0])));
    const int dim = static_cast<int>(v[0]);
    for (std::size_t i = 0; i < d.n; ++i)
      for (int k = dim; k < 3; ++k)
        if (d.x[3 * i + k] != 0.0)
          throw ConfigError("Dimension = " + std::to_string(dim) + " but particle " + std::to_string(i) + " has " +
                            "xyz"[k] + " = " + text(d.x[3 * i + k]));
    return dim;
  }
  auto all_zero = [&](int k) {
    for (std::size_t i = 0; i < d.n; ++i)
      if (d.x[3 * i + k] != 0.0) return false;
    return true;
  };
  return all_zero(2) ? (all_zero(1) ? 1 : 2) : 3;
}

RunConfig restore_own(hid_t file, IcData& d, const std::string& path) {
  h5::Handle g = h5::open_group(file, "SPHSandbox");
  const RunConfig orig = RunConfig::from_json_text(h5::read_attr_string(g.get(), "scene_json"), path + " (/SPHSandbox)");
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
  d.dim = orig.scene->dim;
  for (std::size_t i = 0; i < d.n; ++i)
    for (int k = 0; k < d.dim; ++k) d.x[3 * i + k] -= shift[k];
  if (!d.h.empty() && h_factor > 0.0)
    for (double& h : d.h) h /= h_factor;

  auto spec = std::make_shared<SceneSpec>(*orig.scene);  // its stages, references, bounds and units
  spec->name = path;
  spec->category = "initial condition (HDF5, this code's export of " + orig.scene->name + ")";
  spec->description = std::to_string(d.n) + " particles of scene " + orig.scene->name + " from " +
                      std::filesystem::path(path).filename().string();
  spec->params.clear();  // the particles come from the file: the scene's own values no longer place them
  spec->convergence = {};  // its study varies those values
  spec->density_anchor = nullptr;
  spec->initial_pressure = nullptr;
  spec->defaults = orig.params;
  if (orig.scene->reference) {
    const SceneValues values = orig.values;  // the reference of the scene as it was exported
    auto ref = orig.scene->reference;
    spec->reference = [ref, values](const Params& p, const SceneValues&) { return ref(p, values); };
  }
  auto data = std::make_shared<const IcData>(d);
  spec->build = [data](const Params& p, const SceneValues&) { return place(*data, p, false); };
  RunConfig c;
  c.params = orig.params;
  c.owned_scene = spec;
  c.scene = spec.get();
  return c;
}

RunConfig foreign(hid_t file, hid_t header, IcData& d, int type, const std::string& path) {
  d.dim = read_dimension(header, d);
  if (h5::has_attr(header, "BoxSize")) {
    const std::vector<double> b = h5::read_attr(header, "BoxSize");
    for (int k = 0; k < 3; ++k) d.box[k] = b.empty() ? 0.0 : b[b.size() == 3 ? static_cast<std::size_t>(k) : 0];
  }
  bool periodic = d.box[0] > 0.0;
  if (h5::Handle rp = h5::open_group(file, "RuntimePars"); rp.valid() && h5::has_attr(rp.get(), "PeriodicBoundariesOn"))
    periodic = periodic && h5::read_attr(rp.get(), "PeriodicBoundariesOn").at(0) != 0.0;

  auto spec = std::make_shared<SceneSpec>();
  spec->name = path;
  spec->dim = d.dim;
  spec->units = read_units(file, path);
  const std::string file_name = std::filesystem::path(path).filename().string();
  // the mean spacing: box volume (or the particles' extent) over N
  double volume = 1.0;
  for (int k = 0; k < d.dim; ++k) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < d.n; ++i) {
      lo = std::min(lo, d.x[3 * i + k]);
      hi = std::max(hi, d.x[3 * i + k]);
    }
    volume *= d.box[k] > 0.0 ? d.box[k] : std::max(hi - lo, 1e-300);
  }
  d.spacing = std::pow(volume / static_cast<double>(d.n), 1.0 / d.dim);

  if (type == 1) {
    // G in the file's units (/Units); without them the file is in code units with G = 1
    const bool units = h5::exists(file, "Units");
    const double G = units ? kGravityCgs * spec->units.mass_cgs * spec->units.time_cgs * spec->units.time_cgs /
                                 std::pow(spec->units.length_cgs, 3)
                           : 1.0;
    spec->category = "initial condition (HDF5 N-body particles)";
    spec->description = std::to_string(d.n) + " point masses from " + file_name + " (PartType1), G = " + text(G) +
                        (units ? " from its /Units" : " (no /Units: code units)");
    scenes::make_nbody(*spec, d.n > 2000 ? GravityType::Tree : GravityType::Direct, G);
    spec->defaults.gravity.eps = 0.05 * d.spacing;  // Plummer softening: 1/20 of the mean spacing
    if (d.h.empty()) d.h.assign(d.n, 0.0);
    periodic = false;
  } else {
    spec->category = "initial condition (HDF5 gas, SWIFT/GADGET layout)";
    spec->defaults.gas.gamma = 5.0 / 3.0;  // SWIFT's and GADGET's default adiabatic index
    if (h5::Handle hs = h5::open_group(file, "HydroScheme"); hs.valid() && h5::has_attr(hs.get(), "Adiabatic index"))
      spec->defaults.gas.gamma = h5::read_attr(hs.get(), "Adiabatic index").at(0);
    spec->allow(Slot::Walls, {"none"});
    spec->allow(Slot::Eos, {"ideal_gas", "isothermal"});
    if (!periodic) spec->allow(Slot::Gravity, {"none", "direct", "tree"});
    const Kernel m4(KernelType::M4, d.dim);
    // SmoothingLength: SWIFT's h = H/gamma_K (files with /Units or Dimension), GADGET's h = H; only the
    // start of the Newton-Raphson solve of h here. Absent: eta times the mean spacing.
    const bool swift = h5::exists(file, "Units") || h5::has_attr(header, "Dimension");
    const double factor = swift ? smoothing_length_factor(KernelType::M4, d.dim, IcFormat::Swift)
                                : smoothing_length_factor(KernelType::M4, d.dim, IcFormat::Gadget4);
    if (d.h.empty()) d.h.assign(d.n, m4.default_eta() * d.spacing);
    else
      for (double& h : d.h) h = h > 0.0 ? h / factor : m4.default_eta() * d.spacing;
    spec->description = std::to_string(d.n) + " gas particles from " + file_name + " (" + (swift ? "SWIFT" : "GADGET") +
                        " layout, " + std::to_string(d.dim) + "D, " +
                        (periodic ? "periodic box " + text(d.box[0]) : std::string("open")) + ")";
    if (d.box[0] > 0.0)
      spec->params.push_back({"periodic", periodic ? 1.0 : 0.0, 0, 1, true,
                              "1: the periodic box [0, BoxSize) of the file; 0: open (no boundaries)", "dimensionless"});
  }
  auto data = std::make_shared<const IcData>(d);
  spec->build = [data](const Params& p, const SceneValues& v) {
    const auto it = v.find("periodic");
    return place(*data, p, it != v.end() && it->second != 0.0);
  };
  RunConfig c;
  c.params = spec->defaults;
  c.values = spec->default_values();
  c.owned_scene = spec;
  c.scene = spec.get();
  return c;
}

}  // namespace

bool is_hdf5_path(const std::string& name) {
  return name.ends_with(".hdf5") || name.ends_with(".h5") || name.ends_with(".hdf");
}

RunConfig load_hdf5_ic(const std::string& path) {
  if (!std::filesystem::exists(path)) throw ConfigError(path + ": no such file");
  h5::Handle file = h5::open_file(path);
  if (!file.valid()) throw ConfigError(path + ": not an HDF5 file (or it cannot be read)");
  try {
    h5::Handle header = h5::open_group(file.get(), "Header");
    if (!header.valid()) throw ConfigError("no /Header group: not an initial condition in the SWIFT/GADGET layout");
    refuse_unsupported_header(header.get());
    std::size_t n = 0;
    const int type = particle_type(header.get(), &n);
    IcData d = read_particles(file.get(), type, n);
    RunConfig c = h5::exists(file.get(), "SPHSandbox") ? restore_own(file.get(), d, path)
                                                       : foreign(file.get(), header.get(), d, type, path);
    c.source_file = std::filesystem::absolute(path).string();
    return c;
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    throw ConfigError(msg.starts_with(path) ? msg : path + ": " + msg);
  } catch (const std::exception& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace sph
