// What maps between this code and SWIFT or GADGET-4 apart from the parameter files: kernel names, each
// code's h, the Courant factor through each code's step formula, SWIFT's command line.
#include <cmath>

#include "io/export_box.h"
#include "sph/ic_export.h"
#include "sph/kernel.h"

namespace sph {
namespace {

/// SWIFT's H/h per kernel and dimension (Dehnen & Aly 2012, MNRAS 425, 1068, Table 1; SWIFT's
/// src/kernel_hydro.h uses the same numbers). 0 where SWIFT has no such kernel (Wendland in 1D).
double swift_ratio(const std::string& kernel, int dim) {
  struct Row {
    const char* name;
    double r1, r2, r3;
  };
  static const Row rows[] = {{"cubic-spline", 1.732051, 1.778002, 1.825742},
                             {"quartic-spline", 1.936492, 1.977173, 2.018932},
                             {"quintic-spline", 2.121321, 2.158131, 2.195775},
                             {"wendland-C2", 0.0, 1.897367, 1.936492},
                             {"wendland-C4", 0.0, 2.171239, 2.207940}};
  for (const Row& r : rows)
    if (kernel == r.name) return dim == 1 ? r.r1 : dim == 2 ? r.r2 : r.r3;
  return 0.0;
}
}  // namespace

const char* to_string(IcFormat f) { return f == IcFormat::Swift ? "swift" : "gadget4"; }

bool parse(const std::string& s, IcFormat& out) {
  if (s == "swift") out = IcFormat::Swift;
  else if (s == "gadget4") out = IcFormat::Gadget4;
  else return false;
  return true;
}

KernelMapping kernel_mapping(KernelType k, int dim, IcFormat f) {
  KernelMapping m;
  if (f == IcFormat::Swift) {
    switch (k) {
      case KernelType::M4: m.name = "cubic-spline"; break;
      case KernelType::M5: m.name = "quartic-spline"; break;
      case KernelType::M6: m.name = "quintic-spline"; break;
      case KernelType::WendlandC2: m.name = "wendland-C2"; break;
      case KernelType::WendlandC4: m.name = "wendland-C4"; break;
      case KernelType::Gaussian:
        m = {"quintic-spline", false, 0.0, "SWIFT has no Gaussian; the quintic spline (M6, same support 3h) is used"};
        break;
    }
    if (dim == 1 && (k == KernelType::WendlandC2 || k == KernelType::WendlandC4))
      m = {"quintic-spline", false, 0.0, "SWIFT has no Wendland kernel in 1D; the quintic spline (M6) is used"};
    m.ratio = swift_ratio(m.name, dim);
    return m;
  }
  switch (k) {
    case KernelType::M4: m.name = "CUBIC_SPLINE_KERNEL"; break;
    case KernelType::WendlandC2: m.name = "WENDLAND_C2_KERNEL"; break;
    case KernelType::WendlandC4: m.name = "WENDLAND_C4_KERNEL"; break;
    case KernelType::M5:
    case KernelType::M6:
    case KernelType::Gaussian:
      m = {"WENDLAND_C4_KERNEL", false, 0.0,
           std::string("GADGET-4 has no ") + to_string(k) +
               " kernel; Wendland C4 (smooth, no pairing instability) with the same neighbour number is used"};
      break;
  }
  return m;
}

double smoothing_length_factor(KernelType k, int dim, IcFormat f) {
  const Kernel kernel(k, dim);
  if (f == IcFormat::Gadget4) return kernel.support();  // GADGET's h is the support radius H
  return kernel.support() / kernel_mapping(k, dim, f).ratio;
}

// The hydrodynamic step of each code, H the kernel's support radius and c_bar = (c_i + c_j)/2:
//  - here (physics/courant.h, pair_terms.h signal_speed): dt = cfl h / v_sig, h = H / support,
//    v_sig = max_j c_bar alpha_scale + beta_scale max(0, -2 w_ij) (w_ij = v_ij . r_hat; both scales
//    1 up to alpha = 1, beta = 2);
//  - SWIFT (src/hydro/Minimal/hydro.h hydro_compute_timestep, hydro_signal_velocity):
//    dt = 2 gamma_K CFL_condition h_S / v_sig, gamma_K h_S = H, v_sig = max_j c_i + c_j - 3 mu_ij;
//  - GADGET-4 (src/time_integration/timestep.cc get_timestep_hydro; sph/hydra.cc for MaxSignalVel):
//    dt = 2 CourantFac Hsml / v_sig, Hsml = H, v_sig = max_j c_i + c_j - 3 mu_ij.
// With x = |w| = |mu| the approach speed, the targets' step is 2 F H / (2 c_bar + 3 x) and this code's
// 2 cfl H / (support (2 c_bar + 4 x)): equal where sound dominates (x = 0) for F = cfl / support, while in
// a shock (x >> c_bar) the targets' step is then 4/3 of this code's. F = (3/4) cfl / support is the
// largest factor whose step is nowhere longer than this code's (equal in shocks, 3/4 of it in sound).
// Copying cfl instead made SWIFT's steps up to `support` (2 for M4) times longer: 2D Sedov gained 5.5%
// of its energy by t = 0.1 at CFL_condition = 0.3; at 0.1125 (this mapping of cfl = 0.3) it keeps 1.8e-4.
double courant_factor(double cfl, KernelType k, int dim) { return 0.75 * cfl / Kernel(k, dim).support(); }

std::string swift_run_line(const Params& p, const std::string& param_file) {
  // --limiter: SWIFT's time-step limiter wakes particles a blast reaches on long steps (without it the
  // Sedov blast stops near t = 0.05 wanting a step below dt_min)
  std::string flags = is_nbody(p) ? "--self-gravity"
                                  : std::string("--hydro --limiter") +
                                        (p.physics.gravity != GravityType::None ? " --self-gravity" : "");
  return "swift " + flags + " --threads=2 " + param_file;
}

}  // namespace sph
