// The metadata SWIFT writes into its own snapshots beside /Header and /Units (SWIFT's src/single_io.c,
// src/hydro_properties.c), which readers of SWIFT files expect: yt's SWIFT frontend is chosen by
// /Header Code = "SWIFT" and then opens /RuntimePars, /Policy, /Parameters, /HydroScheme and
// /SubgridScheme. SWIFT ignores all of it when it reads an initial condition. No units here: lengths are
// the file's (/Units), gamma_K is a number.
#include "io/hdf5_swift_groups.h"

#include "io/hdf5_util.h"

namespace sph {

void write_swift_groups(hid_t file, const SwiftGroups& s) {
  {
    h5::Handle header = h5::open_group(file, "Header");
    h5::write_attr(header.get(), "Code", std::string("SWIFT"));  // fixed-length ASCII, as SWIFT writes it
  }
  {
    h5::Handle rp = h5::create_group(file, "RuntimePars");
    h5::write_attr_int(rp.get(), "PeriodicBoundariesOn", s.periodic ? 1 : 0);
  }
  {
    h5::Handle policy = h5::create_group(file, "Policy");
    h5::write_attr_int(policy.get(), "cosmological integration", 0);
    h5::write_attr_int(policy.get(), "hydro", s.hydro ? 1 : 0);
    h5::write_attr_int(policy.get(), "self gravity", s.self_gravity ? 1 : 0);
  }
  h5::create_group(file, "Parameters");     // SWIFT: the YAML parameters; here none (they are in /SPHSandbox)
  h5::create_group(file, "SubgridScheme");  // SWIFT: cooling, star formation, ...; none here
  h5::Handle hydro = h5::open_group(file, "HydroScheme");
  if (s.hydro && hydro.valid()) {
    // SmoothingLength holds SWIFT's h; the kernel reaches to H = gamma_K h
    h5::write_attr(hydro.get(), "Kernel function", s.kernel_name);
    h5::write_attr(hydro.get(), "Kernel gamma", s.kernel_gamma);
    h5::write_attr_int(hydro.get(), "Dimension", s.dim);
  }
}

}  // namespace sph
