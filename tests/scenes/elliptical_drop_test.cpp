// The elliptical drop (seed 001 §7.1) at dx = 0.05 (1257 particles): semi-axes against the
// incompressible ODE, and seed 001 Fig. 1b's finding that the corrected and standard-corrected
// formulations keep ab = 1 better than the standard one. Measured at this resolution (t = 7.6 ms):
// |ab - 1| = 7.4% standard, 1.7% standard-corrected, 1.0% corrected; major axis within 0.3%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sph/world.h"

namespace sph {
namespace {

struct Axes {
  double err_major, err_minor, err_ab, P_norm;
};

Axes run_drop(const std::string& force, double t) {
  RunConfig cfg = RunConfig::from_scene("elliptical_drop");
  cfg.set("scene.dx", "0.05", "test");
  cfg.set("physics.force", force, "test");
  if (force == "standard") cfg.set("physics.xsph", "on", "test");  // seed 001 eqs. 44-47
  if (force == "corrected") {  // seed 001 §5.2: a viscous fluid, no artificial viscosity
    cfg.set("physics.viscosity", "laplacian", "test");
    cfg.set("visc.nu", "0.01", "test");
  }
  cfg.validate();
  World w(cfg);
  w.advance_to(t);
  const Diagnostics d = w.report().diagnostics();
  const Axes a{w.report().reference_value("err_major"), w.report().reference_value("err_minor"), w.report().reference_value("err_ab"),
               std::hypot(d.P[0], d.P[1])};
  std::printf("%s t=%g: err_major %.4f err_minor %.4f |ab-1| %.4f |P| %.3g\n", force.c_str(), t, a.err_major,
              a.err_minor, a.err_ab, a.P_norm);
  return a;
}

TEST(EllipticalDrop, SemiAxesFollowTheIncompressibleOde) {
  const Axes mid = run_drop("standard_corrected", 0.0038);
  EXPECT_LT(mid.err_major, 0.01);
  EXPECT_LT(mid.err_minor, 0.02);
  const Axes end = run_drop("standard_corrected", 0.0076);
  EXPECT_LT(end.err_major, 0.01);   // measured 0.29%
  EXPECT_LT(end.err_ab, 0.025);     // measured 1.7% (0.7% at dx = 0.025)
  // the pairwise corrected form conserves momentum (the drop is symmetric: P = 0 exactly would need
  // exact symmetry of the sums; round-off only)
  EXPECT_LT(end.P_norm, 1e-6);
}

TEST(EllipticalDrop, CorrectedFormulationsKeepTheAreaBetterThanTheStandardOne) {
  const Axes standard = run_drop("standard", 0.0076);
  const Axes sc = run_drop("standard_corrected", 0.0076);
  const Axes corrected = run_drop("corrected", 0.0076);
  EXPECT_LT(standard.err_major, 0.01);
  EXPECT_LT(corrected.err_major, 0.01);
  EXPECT_LT(sc.err_ab, standard.err_ab);
  EXPECT_LT(corrected.err_ab, standard.err_ab);
  EXPECT_GT(standard.err_ab, 0.03);  // the standard kernel gradient loses area at the free surface (7.4%)
}

}  // namespace
}  // namespace sph
