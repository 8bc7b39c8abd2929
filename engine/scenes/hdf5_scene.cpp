// The scene of an HDF5 initial condition (sph/hdf5_ic.h): the particles read by io/hdf5_ic.cpp placed as
// a scene. This code's own exports come back as the scene they were exported from; other codes' files
// run as an ideal gas or as N-body point masses with defaults taken from the file's header.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "io/hdf5_ic_file.h"
#include "nbody_common.h"
#include "scene_util.h"
#include "sph/hdf5_ic.h"
#include "sph/ic_export.h"
#include "sph/kernel.h"

namespace sph {
namespace {

constexpr double kGravityCgs = 6.67430e-8;  // CODATA 2018 [cm^3 g^-1 s^-2]

/// The scene that places the file's particles.
SceneSetup place(const IcData& d, const Params& prm, bool periodic) {
  Particles p = scenes::make_particles(prm, d.dim, d.n);
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
                            std::string(1, "xyz"[k]) + " has " + ic_text(d.box[k]) + ")");
        s.domain.bc[k] = Boundary::Periodic;
      }
      if (prm.physics.gravity != GravityType::None)
        throw ConfigError("self-gravity needs an open box: set scene.periodic = 0");
    }
  }
  return s;
}

/// The run configuration of a scene built here: it owns its scene.
RunConfig config_of(std::shared_ptr<SceneSpec> spec, const Params& params) {
  RunConfig c;
  c.params = params;
  c.owned_scene = spec;
  c.scene = spec.get();
  return c;
}

/// This code's export: the scene it was exported from (stages, references, bounds, units), placing the
/// file's particles instead of its own.
RunConfig own_scene(const IcFile& f, const std::string& path) {
  const IcData& d = f.data;
  const RunConfig& orig = f.exported;
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
  SceneValues values = orig.scene->default_values();  // its reference's assumptions, judged on them too
  for (const auto& [k, v] : orig.values) values[k] = v;
  for (RefAssumption& a : spec->assumptions) {
    if (a.value) {
      a.value = [f = a.value, values](const Params& p, const SceneValues&) { return f(p, values); };
    } else if (a.key.starts_with("scene.")) {
      const auto it = values.find(a.key.substr(6));
      const double v = it == values.end() ? std::nan("") : it->second;
      a.value = [v](const Params&, const SceneValues&) { return v; };
    }
  }
  auto data = std::make_shared<const IcData>(d);
  spec->build = [data](const Params& p, const SceneValues&) { return place(*data, p, false); };
  return config_of(spec, orig.params);
}

/// The mean spacing: the box volume (or the particles' extent) over N.
double mean_spacing(const IcData& d) {
  double volume = 1.0;
  for (int k = 0; k < d.dim; ++k) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < d.n; ++i) {
      lo = std::min(lo, d.x[3 * i + k]);
      hi = std::max(hi, d.x[3 * i + k]);
    }
    volume *= d.box[k] > 0.0 ? d.box[k] : std::max(hi - lo, 1e-300);
  }
  return std::pow(volume / static_cast<double>(d.n), 1.0 / d.dim);
}

/// Point masses (PartType1) under direct or tree gravity, G in the file's units (/Units); without them
/// the file is in code units with G = 1.
void nbody_scene(SceneSpec& spec, IcData& d, const IcForeignHeader& fh, const std::string& file_name) {
  const double G = fh.has_units ? kGravityCgs * spec.units.mass_cgs * spec.units.time_cgs * spec.units.time_cgs /
                                      std::pow(spec.units.length_cgs, 3)
                                : 1.0;
  spec.category = "initial condition (HDF5 N-body particles)";
  spec.description = std::to_string(d.n) + " point masses from " + file_name + " (PartType1), G = " + ic_text(G) +
                     (fh.has_units ? " from its /Units" : " (no /Units: code units)");
  scenes::make_nbody(spec, d.n > 2000 ? GravityType::Tree : GravityType::Direct, G);
  spec.defaults.gravity.eps = 0.05 * d.spacing;  // Plummer softening: 1/20 of the mean spacing
  if (d.h.empty()) d.h.assign(d.n, 0.0);
}

/// Gas (PartType0): an ideal gas of the file's adiabatic index (else 5/3), periodic in its box unless
/// scene.periodic = 0.
void gas_scene(SceneSpec& spec, IcData& d, const IcForeignHeader& fh, const std::string& file_name) {
  spec.category = "initial condition (HDF5 gas, SWIFT/GADGET layout)";
  spec.defaults.gas.gamma = 5.0 / 3.0;  // SWIFT's and GADGET's default adiabatic index
  if (fh.adiabatic_index) spec.defaults.gas.gamma = *fh.adiabatic_index;
  spec.allow(Slot::Walls, {"none"});
  spec.allow(Slot::Eos, {"ideal_gas", "isothermal"});
  if (!fh.periodic) spec.allow(Slot::Gravity, {"none", "direct", "tree", "fmm"});
  const Kernel m4(KernelType::M4, d.dim);
  // SmoothingLength: SWIFT's h = H/gamma_K (files with /Units or Dimension), GADGET's h = H; only the
  // start of the Newton-Raphson solve of h here. Absent: eta times the mean spacing.
  const double factor = fh.swift ? smoothing_length_factor(KernelType::M4, d.dim, IcFormat::Swift)
                                 : smoothing_length_factor(KernelType::M4, d.dim, IcFormat::Gadget4);
  if (d.h.empty()) d.h.assign(d.n, m4.default_eta() * d.spacing);
  else
    for (double& h : d.h) h = h > 0.0 ? h / factor : m4.default_eta() * d.spacing;
  spec.description = std::to_string(d.n) + " gas particles from " + file_name + " (" +
                     (fh.swift ? "SWIFT" : "GADGET") + " layout, " + std::to_string(d.dim) + "D, " +
                     (fh.periodic ? "periodic box " + ic_text(d.box[0]) : std::string("open")) + ")";
  if (d.box[0] > 0.0)
    spec.params.push_back({"periodic", fh.periodic ? 1.0 : 0.0, 0, 1, true,
                           "1: the periodic box [0, BoxSize) of the file; 0: open (no boundaries)", "dimensionless"});
}

/// Another code's file: gas or point masses, with defaults from its header.
RunConfig foreign_scene(const IcFile& f, const std::string& path) {
  IcData d = f.data;
  auto spec = std::make_shared<SceneSpec>();
  spec->name = path;
  spec->dim = d.dim;
  spec->units = f.foreign.units;
  d.spacing = mean_spacing(d);
  const std::string file_name = std::filesystem::path(path).filename().string();
  if (f.type == 1) nbody_scene(*spec, d, f.foreign, file_name);
  else gas_scene(*spec, d, f.foreign, file_name);
  auto data = std::make_shared<const IcData>(d);
  spec->build = [data](const Params& p, const SceneValues& v) {
    const auto it = v.find("periodic");
    return place(*data, p, it != v.end() && it->second != 0.0);
  };
  RunConfig c = config_of(spec, spec->defaults);
  c.values = spec->default_values();
  return c;
}

}  // namespace

RunConfig load_hdf5_ic(const std::string& path) {
  const IcFile f = read_hdf5_ic(path);
  RunConfig c = f.data.own ? own_scene(f, path) : foreign_scene(f, path);
  c.source_file = f.absolute_path;
  return c;
}

}  // namespace sph
