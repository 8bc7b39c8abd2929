// Kernel mapping and the parameter files of SWIFT (YAML) and GADGET-4 (param.txt + Config.sh options).
#include "sph/ic_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "text/number_text.h"
#include "io/export_box.h"
#include "io/swift_softening.h"
#include "sph/kernel.h"

namespace sph {
namespace {

std::string num(double v) { return g_text(v, 10); }

double ball_volume(int dim) { return dim == 1 ? 2.0 : dim == 2 ? std::numbers::pi : 4.0 * std::numbers::pi / 3.0; }

/// The stage choices a target code cannot reproduce, as warnings.
void physics_warnings(const World& world, IcFormat f, std::vector<std::string>* w) {
  const Physics& ph = world.params().physics;
  const std::string code = f == IcFormat::Swift ? "SWIFT" : "GADGET-4";
  if (ph.eos == EosType::Tait || ph.eos == EosType::Polytropic)
    w->push_back("physics.eos = " + ph.get(Slot::Eos) + ": " + code + " runs ideal or isothermal gases only");
  if (ph.force == ForceType::Corrected || ph.force == ForceType::StandardCorrected)
    w->push_back("physics.force = " + ph.get(Slot::Force) + ": " + code + " has no corrected-gradient SPH");
  if (ph.density == DensityMode::Continuity)
    w->push_back("physics.density = continuity: " + code + " sums the density");
  if (ph.walls != WallType::None)
    w->push_back("physics.walls = " + ph.get(Slot::Walls) + ": " + code +
                 " has no fixed wall particles (they are written as gas, with this code's own Kind dataset)");
  if (ph.body_force != BodyForce::None)
    w->push_back("physics.body_force = " + ph.get(Slot::BodyForce) + ": not written to the parameter file (" + code +
                 " needs an external-potential module for it)");
  if (ph.xsph == Toggle::On) w->push_back("physics.xsph = on: " + code + " has no XSPH");
  if (ph.conduction == Toggle::On)  // 3D Sedov at t = 0.1: R 0.4890 here with it, 0.4758 without, SWIFT 0.4729
    w->push_back("physics.conduction = on: " + code + (f == IcFormat::Swift ? "'s minimal scheme" : "") +
                 " has no artificial conduction (compare with --set physics.conduction=none here)");
  if (ph.viscosity == ViscType::Laplacian)
    w->push_back("physics.viscosity = laplacian: " + code + " has artificial viscosity only");
  for (int axis : export_box(world).wall_axes)
    w->push_back(std::string("mirror walls on axis ") + "xyz"[axis] + ": " + code +
                 " has none, so its box is periodic there (the states meet again at the box's edge, as in SWIFT's "
                 "own Sod example): compare only until waves reach it");
}

/// What both parameter files start from: the scene's parameters, units, kernel and its mapping, box.
struct Target {
  Target(const World& world, IcFormat f, std::vector<std::string>* w)
      : prm(world.params()), u(world.config().scene->units), dim(world.particles().dim()), nbody(is_nbody(prm)),
        kernel(prm.kernel.type, dim), km(kernel_mapping(prm.kernel.type, dim, f)), box(export_box(world)) {
    if (!nbody && !km.exact) w->push_back("kernel.type = " + std::string(to_string(prm.kernel.type)) + ": " + km.note);
  }
  double eta() const { return prm.kernel.eta > 0.0 ? prm.kernel.eta : kernel.default_eta(); }
  const Params& prm;
  const UnitSystem& u;
  int dim;
  bool nbody;
  Kernel kernel;
  KernelMapping km;
  ExportBox box;
};

/// SWIFT's Gravity block. Plummer's law has no SWIFT counterpart: the softening written gives the same
/// potential energy now (io/swift_softening.h), and eta the same step as this code's Plummer limit:
/// SWIFT's sqrt(2 eta eps_S / |a|) (src/gravity/MultiSoftening/gravity.h) = cfl sqrt(eps / |a|) here.
std::string swift_gravity(const World& world, std::vector<std::string>* w) {
  const Params& prm = world.params();
  const double eps = prm.gravity.eps > 0.0 ? prm.gravity.eps : world.report().spacing() * 0.1;
  double eps_s = eps, eta = 0.025;
  if (prm.gravity.softening == Softening::Plummer && prm.gravity.eps > 0.0) {
    const Particles& p = world.particles();
    eps_s = swift_softening_matching_plummer(p, p.size(), eps);
    if (eps_s > 0.0) {
      eta = prm.time.cfl * prm.time.cfl * eps / (2.0 * eps_s);
      w->push_back("gravity.softening = plummer: SWIFT softens with a kernel, Newtonian beyond 3 eps; eps = " +
                   num(eps_s) + " gives this state's potential energy (this code's eps = " + num(eps) +
                   "), the forces differ within a few eps");
    } else {
      eps_s = eps;
      w->push_back("gravity.softening = plummer: SWIFT softens with a kernel, Newtonian beyond 3 eps; above " +
                   std::to_string(kSoftMatchMaxN) + " particles eps is not matched, so SWIFT's potential energy "
                   "is lower than this code's");
    }
  }
  return "Gravity:\n  eta:      " + num(eta) + "\n  MAC:      geometric\n  theta_cr: " + num(prm.gravity.theta) +
         "\n  max_physical_DM_softening:     " + num(eps_s) + "\n  max_physical_baryon_softening: " + num(eps_s) +
         "\n  comoving_DM_softening:         " + num(eps_s) + "\n  comoving_baryon_softening:     " + num(eps_s) +
         "\n\nPhysicalConstants:\n  G: " + num(prm.gravity.G) + "\n\n";
}

std::string swift_file(const World& world, const std::string& ic_file, std::vector<std::string>* w) {
  const Target t(world, IcFormat::Swift, w);
  const auto& [prm, u, dim, nbody, kernel, km, box] = t;
  std::string configure = "./configure --with-hydro-dimension=" + std::to_string(dim);
  if (!nbody) {
    configure += " --with-kernel=" + km.name + " --with-hydro=minimal";
    const double g = prm.gas.gamma;
    const char* index = std::abs(g - 5.0 / 3.0) < 1e-9 ? "5/3"
                        : std::abs(g - 1.4) < 1e-9     ? "7/5"
                        : std::abs(g - 4.0 / 3.0) < 1e-9 ? "4/3"
                        : std::abs(g - 2.0) < 1e-9     ? "2"
                                                       : nullptr;
    if (prm.physics.eos == EosType::Isothermal) configure += " --with-equation-of-state=isothermal-gas";
    else if (index) configure += std::string(" --with-adiabatic-index=") + index;
    else w->push_back("gas.gamma = " + num(g) + ": SWIFT compiles only 5/3, 7/5, 4/3 or 2 (--with-adiabatic-index)");
  }
  // outputs every dt_out, but no longer than the run: SWIFT refuses a dt_max beyond time_end - time_begin
  // (evrard exported with --until 0.01 and dt_max 0.1: "Maximal time-step size larger than the simulation run time")
  const double run = prm.time.t_end - world.time();
  const double dt_out = std::min(prm.time.dt_out > 0.0 ? prm.time.dt_out : prm.time.t_end, run > 0.0 ? run : prm.time.t_end);
  std::string s = "# SWIFT parameter file for " + ic_file + ", written by `sph export-ics " + world.config().scene->name +
                  " --format swift`.\n# Build SWIFT with:\n#   " + configure + "\n# Run: " +
                  swift_run_line(prm, "PARAMETER_FILE") + "\n# Scene units: " + u.name + ".\n\n";
  s += "InternalUnitSystem:\n  UnitMass_in_cgs:     " + num(u.mass_cgs) + "\n  UnitLength_in_cgs:   " +
       num(u.length_cgs) + "\n  UnitVelocity_in_cgs: " + num(u.length_cgs / u.time_cgs) +
       "\n  UnitCurrent_in_cgs:  1\n  UnitTemp_in_cgs:     1\n\n";
  s += "TimeIntegration:\n  time_begin: " + num(world.time()) + "\n  time_end:   " + num(prm.time.t_end) +
       "\n  dt_min:     " + num(prm.time.t_end * 1e-10) + "\n  dt_max:     " + num(dt_out) + "\n\n";
  s += "Snapshots:\n  basename:   " + world.config().scene->name + "\n  time_first: " + num(world.time()) +
       "\n  delta_time: " + num(dt_out) + "\n\nStatistics:\n  delta_time: " + num(dt_out / 10.0) + "\n\n";
  if (!nbody) {
    // the same support radius in units of the particle spacing: H = support eta dx = gamma_K eta_swift dx
    const double cfl = prm.time.cfl;
    s += "SPH:\n  resolution_eta:  " + num(kernel.support() * t.eta() / km.ratio) + "   # this code's kernel.eta = " +
         num(t.eta()) + ", support " + num(kernel.support()) + " h\n  CFL_condition:   " +
         num(courant_factor(cfl, prm.kernel.type, dim)) + "   # time.cfl = " + num(cfl) +
         " here: 3/4 cfl / support, never a longer step\n  h_tolerance:     " + num(prm.h.tol) + "\n";
    if (prm.physics.viscosity == ViscType::Monaghan)
      s += "  viscosity_alpha: " + num(prm.visc.alpha) + "   # beta = 2 alpha in SWIFT; this code's visc.beta = " +
           num(prm.visc.beta) + "\n";
    if (prm.physics.eos == EosType::Isothermal)
      s += "\nEoS:\n  isothermal_internal_energy: " + num(prm.gas.cs * prm.gas.cs / (prm.gas.gamma - 1.0)) + "\n";
    s += "\n";
  }
  if (prm.physics.gravity != GravityType::None) s += swift_gravity(world, w);
  s += "InitialConditions:\n  file_name: ./" + ic_file + "\n  periodic:  " + std::string(box.periodic ? "1" : "0") +
       "\n";
  return s;
}

/// GADGET-4's Config.sh options for the target, one a line (a warning when a periodic box is not a cube).
std::string gadget4_config(const Target& t, std::vector<std::string>* w) {
  const auto& [prm, u, dim, nbody, kernel, km, box] = t;
  if (box.periodic) {
    bool cube = true;
    for (int k = 1; k < dim; ++k) cube = cube && std::abs(box.size[k] - box.size[0]) <= 1e-12 * box.size[0];
    if (!cube) w->push_back("the box is not a cube: GADGET-4's periodic box is a cube of side BoxSize (its LONG_X_BITS options "
                            "shorten a side by powers of 2); the largest side is written");
  }
  std::string config = box.periodic ? "PERIODIC\n" : "";
  if (dim == 2) config += "TWODIMS\n";
  if (dim == 1) config += "ONEDIMS\n";
  if (prm.physics.gravity != GravityType::None || nbody) config += "SELFGRAVITY\n";
  if (!nbody) {
    config += km.name + "\n";
    if (prm.physics.eos == EosType::Isothermal) config += "ISOTHERM_EQS\n";
    else config += "GAMMA=" + num(prm.gas.gamma) + "\n";
  }
  config += "DOUBLEPRECISION=1\nIDS_64BIT\n";
  return config;
}

std::string gadget4_file(const World& world, const std::string& ic_file, std::vector<std::string>* w) {
  const Target t(world, IcFormat::Gadget4, w);
  const auto& [prm, u, dim, nbody, kernel, km, box] = t;
  const std::string config = gadget4_config(t, w);
  std::string s = "% GADGET-4 parameter file for " + ic_file + ", written by `sph export-ics " + world.config().scene->name +
                  " --format gadget4`.\n% Compile GADGET-4 with these Config.sh options:\n";
  for (std::size_t a = 0, b; a < config.size(); a = b + 1) {
    b = config.find('\n', a);
    s += "%   " + config.substr(a, b - a) + "\n";
  }
  s += "% Scene units: " + u.name + ".\n\n";
  const double dt_out = prm.time.dt_out > 0.0 ? prm.time.dt_out : prm.time.t_end;
  double side = 0.0;
  if (box.periodic)
    for (int k = 0; k < dim; ++k) side = std::max(side, box.size[k]);
  auto line = [&](const std::string& key, const std::string& value) {
    std::string k = key;
    k.resize(std::max<std::size_t>(k.size() + 1, 34), ' ');
    s += k + value + "\n";
  };
  line("InitCondFile", ic_file.substr(0, ic_file.rfind(".hdf5")));
  line("OutputDir", "./output");
  line("SnapshotFileBase", "snapshot");
  line("OutputListFilename", "empty.txt");
  line("ICFormat", "3");
  line("SnapFormat", "3");
  line("TimeLimitCPU", "86400");
  line("CpuTimeBetRestartFile", "7200");
  line("MaxMemSize", "2000");
  line("TimeBegin", num(world.time()));
  line("TimeMax", num(prm.time.t_end));
  line("ComovingIntegrationOn", "0");
  line("Omega0", "0");
  line("OmegaLambda", "0");
  line("OmegaBaryon", "0");
  line("HubbleParam", "1.0");
  line("Hubble", "0");
  line("BoxSize", num(side));
  line("OutputListOn", "0");
  line("TimeBetSnapshot", num(dt_out));
  line("TimeOfFirstSnapshot", num(world.time()));
  line("TimeBetStatistics", num(dt_out / 10.0));
  line("NumFilesPerSnapshot", "1");
  line("MaxFilesWithConcurrentIO", "1");
  line("ErrTolIntAccuracy", "0.025");
  line("CourantFac", num(courant_factor(prm.time.cfl, prm.kernel.type, dim)));  // 3/4 cfl / support
  line("MaxSizeTimestep", num(dt_out));
  line("MinSizeTimestep", "0");
  line("TypeOfOpeningCriterion", "1");
  line("ErrTolTheta", num(prm.gravity.theta));
  line("ErrTolThetaMax", "0.9");
  line("ErrTolForceAcc", "0.005");
  line("TopNodeFactor", "2.5");
  line("ActivePartFracForNewDomainDecomp", "0.01");
  // neighbours inside the support radius H = support eta dx on a lattice: V_d (support eta)^d
  line("DesNumNgb", num(std::round(ball_volume(dim) * std::pow(kernel.support() * t.eta(), dim))));
  line("MaxNumNgbDeviation", dim == 1 ? "0.1" : "1");
  line("UnitLength_in_cm", num(u.length_cgs));
  line("UnitMass_in_g", num(u.mass_cgs));
  line("UnitVelocity_in_cm_per_s", num(u.length_cgs / u.time_cgs));
  line("GravityConstantInternal", num(prm.gravity.G));
  const double eps = prm.gravity.eps > 0.0 ? prm.gravity.eps : std::max(world.report().spacing() * 0.1, 1e-6);
  line("SofteningComovingClass0", num(eps));
  line("SofteningMaxPhysClass0", num(eps));
  for (int t = 0; t < 6; ++t) line("SofteningClassOfPartType" + std::to_string(t), "0");
  line("ArtBulkViscConst", num(prm.physics.viscosity == ViscType::Monaghan ? prm.visc.alpha : 0.0));
  line("MinEgySpec", "0");
  line("InitGasTemp", "0");
  return s;
}

}  // namespace

std::string parameter_file(const World& world, IcFormat format, const std::string& ic_file,
                           std::vector<std::string>* warnings) {
  std::vector<std::string> local;
  std::vector<std::string>* w = warnings ? warnings : &local;
  physics_warnings(world, format, w);
  return format == IcFormat::Swift ? swift_file(world, ic_file, w) : gadget4_file(world, ic_file, w);
}

}  // namespace sph
