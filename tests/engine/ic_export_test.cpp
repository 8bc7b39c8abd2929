// The mapping to SWIFT and GADGET-4 (sph/ic_export.h): kernels and their H/h (Dehnen & Aly 2012),
// smoothing lengths in each code's convention, and what the parameter files say.
#include "sph/ic_export.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <cstdint>

#include "io/swift_softening.h"

namespace sph {
namespace {

TEST(KernelMapping, SplinesAndWendlandsMapOneToOne) {
  EXPECT_EQ(kernel_mapping(KernelType::M4, 3, IcFormat::Swift).name, "cubic-spline");
  EXPECT_EQ(kernel_mapping(KernelType::M6, 2, IcFormat::Swift).name, "quintic-spline");
  EXPECT_EQ(kernel_mapping(KernelType::WendlandC2, 3, IcFormat::Swift).name, "wendland-C2");
  EXPECT_TRUE(kernel_mapping(KernelType::M5, 1, IcFormat::Swift).exact);
  EXPECT_EQ(kernel_mapping(KernelType::M4, 2, IcFormat::Gadget4).name, "CUBIC_SPLINE_KERNEL");
  EXPECT_EQ(kernel_mapping(KernelType::WendlandC4, 3, IcFormat::Gadget4).name, "WENDLAND_C4_KERNEL");
}

TEST(KernelMapping, WhatTheTargetLacksIsNamed) {
  const KernelMapping g = kernel_mapping(KernelType::Gaussian, 3, IcFormat::Swift);
  EXPECT_FALSE(g.exact);
  EXPECT_EQ(g.name, "quintic-spline");
  EXPECT_NE(g.note.find("no Gaussian"), std::string::npos);
  EXPECT_FALSE(kernel_mapping(KernelType::WendlandC2, 1, IcFormat::Swift).exact);  // no 1D Wendland in SWIFT
  EXPECT_FALSE(kernel_mapping(KernelType::M6, 3, IcFormat::Gadget4).exact);
}

TEST(SmoothingLength, EachCodesConvention) {
  // SWIFT: h = H / gamma_K with H the support radius (2h for M4 here); Dehnen & Aly Table 1
  EXPECT_NEAR(smoothing_length_factor(KernelType::M4, 3, IcFormat::Swift), 2.0 / 1.825742, 1e-15);
  EXPECT_NEAR(smoothing_length_factor(KernelType::M4, 1, IcFormat::Swift), 2.0 / 1.732051, 1e-15);
  EXPECT_NEAR(smoothing_length_factor(KernelType::M6, 2, IcFormat::Swift), 3.0 / 2.158131, 1e-15);
  // GADGET-4: h is the support radius itself
  EXPECT_EQ(smoothing_length_factor(KernelType::M4, 2, IcFormat::Gadget4), 2.0);
  EXPECT_EQ(smoothing_length_factor(KernelType::WendlandC2, 3, IcFormat::Gadget4), 2.0);
}

TEST(ParameterFile, SwiftGetsTheSameSupportInSpacings) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "50", "test");
  const World w(cfg);
  std::vector<std::string> warnings;
  const std::string yml = parameter_file(w, IcFormat::Swift, "sod.hdf5", &warnings);
  // H = 2 * 1.2 dx here; SWIFT's H = 1.732051 eta dx: eta = 2.4 / 1.732051
  char eta[64];
  std::snprintf(eta, sizeof eta, "resolution_eta:  %.10g", 2.4 / 1.732051);
  EXPECT_NE(yml.find(eta), std::string::npos) << yml;
  EXPECT_NE(yml.find("--with-hydro-dimension=1 --with-kernel=cubic-spline --with-hydro=minimal --with-adiabatic-index=7/5"),
            std::string::npos);
  EXPECT_NE(yml.find("time_end:   0.2"), std::string::npos);
  EXPECT_NE(yml.find("file_name: ./sod.hdf5"), std::string::npos);
  EXPECT_NE(yml.find("periodic:  1"), std::string::npos);
  bool walls = false;
  for (const std::string& m : warnings) walls = walls || m.find("mirror walls on axis x") != std::string::npos;
  EXPECT_TRUE(walls);
}

TEST(ParameterFile, SwiftStepsAndOutputsFitARunShorterThanItsOutputInterval) {
  // evrard outputs every 0.1; exported to run to 0.01, SWIFT refused dt_max 0.1 > time_end - time_begin
  RunConfig cfg = RunConfig::from_scene("evrard");
  cfg.set("scene.n", "500", "test");
  cfg.set("time.t_end", "0.01", "test");
  const World w(cfg);
  std::vector<std::string> warnings;
  const std::string yml = parameter_file(w, IcFormat::Swift, "evrard.hdf5", &warnings);
  EXPECT_NE(yml.find("dt_max:     0.01\n"), std::string::npos) << yml;
}

TEST(ParameterFile, Gadget4GetsItsNeighbourNumberAndConfigOptions) {
  RunConfig cfg = RunConfig::from_scene("box_lattice");
  const World w(cfg);
  std::vector<std::string> warnings;
  const std::string txt = parameter_file(w, IcFormat::Gadget4, "box.hdf5", &warnings);
  // 2D M4 at eta 1.2: pi (2 * 1.2)^2 = 18.1 neighbours inside the support
  EXPECT_NE(txt.find("DesNumNgb                         18"), std::string::npos) << txt;
  EXPECT_NE(txt.find("%   TWODIMS"), std::string::npos);
  EXPECT_NE(txt.find("%   PERIODIC"), std::string::npos);
  EXPECT_NE(txt.find("%   GAMMA=1.4"), std::string::npos);
  EXPECT_NE(txt.find("InitCondFile                      box"), std::string::npos);
  EXPECT_NE(txt.find("BoxSize                           1"), std::string::npos);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(CourantFactor, ThroughEachCodesStepFormula) {
  // SWIFT and GADGET-4: dt = 2 F H / v_sig with v_sig = c_i + c_j + 3|mu|; here dt = cfl (H / support) /
  // (c_bar + 2|w|): (3/4) cfl / support, so never a longer step (copying cfl made SWIFT's twice as long)
  EXPECT_DOUBLE_EQ(courant_factor(0.3, KernelType::M4, 2), 0.1125);
  EXPECT_DOUBLE_EQ(courant_factor(0.3, KernelType::M6, 3), 0.075);
  for (double x : {0.0, 0.5, 1.0, 4.0, 100.0}) {  // approach speed over c_bar = 1, H = 1
    const double cfl = 0.3, F = courant_factor(cfl, KernelType::M4, 2);
    const double here = cfl / 2.0 / (1.0 + 2.0 * x), target = 2.0 * F / (2.0 + 3.0 * x);
    EXPECT_LE(target, here * (1.0 + 1e-12)) << "x = " << x;
    EXPECT_GE(target, 0.75 * here * (1.0 - 1e-12)) << "x = " << x;
  }
}

TEST(ParameterFile, SwiftKeysTheMappedCflAndTheLimiter) {
  RunConfig cfg = RunConfig::from_scene("sedov");
  cfg.set("scene.n_side", "40", "test");
  const World w(cfg);
  std::vector<std::string> warnings;
  const std::string yml = parameter_file(w, IcFormat::Swift, "sedov.hdf5", &warnings);
  EXPECT_NE(yml.find("CFL_condition:   0.1125 "), std::string::npos) << yml;  // time.cfl 0.3, M4
  EXPECT_NE(yml.find("  h_tolerance:     1e-06\n"), std::string::npos);        // SWIFT's key
  EXPECT_EQ(yml.find("h_relative_tolerance"), std::string::npos);
  EXPECT_NE(yml.find("# Run: swift --hydro --limiter --threads=2"), std::string::npos);
  EXPECT_EQ(swift_run_line(w.params(), "s.yml"), "swift --hydro --limiter --threads=2 s.yml");
  bool conduction = false;
  for (const std::string& m : warnings) conduction = conduction || m.find("physics.conduction") != std::string::npos;
  EXPECT_TRUE(conduction);
  const std::string txt = parameter_file(w, IcFormat::Gadget4, "sedov.hdf5", &warnings);
  EXPECT_NE(txt.find("CourantFac                        0.1125"), std::string::npos) << txt;
}

TEST(SwiftSoftening, SamePotentialEnergyAsPlummer) {
  // two unit masses 0.2 apart, Plummer eps = 0.1: SWIFT's phi(r, H = 3 eps_S) = -1/sqrt(r^2 + eps^2)
  Particles p(3, 2, FieldSet{}.add(Field::Mass));
  p.x[0][1] = 0.2;
  p[Field::Mass][0] = p[Field::Mass][1] = 1.0;
  const double eps_s = swift_softening_matching_plummer(p, 2, 0.1);
  const double u = 0.2 / (3.0 * eps_s), u2 = u * u, u4 = u2 * u2;
  const double phi = (3 * u4 * u2 * u - 15 * u4 * u2 + 28 * u4 * u - 21 * u4 + 7 * u2 - 3) / (3.0 * eps_s);
  EXPECT_LT(u, 1.0);
  EXPECT_NEAR(phi, -1.0 / std::sqrt(0.04 + 0.01), 1e-8);
  EXPECT_EQ(swift_softening_matching_plummer(p, kSoftMatchMaxN + 1, 0.1), 0.0);  // too many: not matched
}

TEST(SwiftSoftening, SameForAnyThreadCount) {
  // 3000 masses on a pseudo-random cloud (the pair sums in parallel rows): eps_S bit for bit on 1 and 2 threads
  const std::size_t n = 3000;
  Particles p(3, n, FieldSet{}.add(Field::Mass));
  std::uint64_t state = 12345;
  auto next = [&] { state = state * 6364136223846793005ull + 1442695040888963407ull; return double(state >> 11) * 0x1p-53; };
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) p.x[k][i] = next();
    p[Field::Mass][i] = 1.0 / n;
  }
  const int full = omp_get_max_threads();
  omp_set_num_threads(1);
  const double one = swift_softening_matching_plummer(p, n, 0.05);
  omp_set_num_threads(2);
  const double two = swift_softening_matching_plummer(p, n, 0.05);
  omp_set_num_threads(full);
  EXPECT_GT(one, 0.05);  // SWIFT's law is Newtonian sooner: a larger eps_S gives Plummer's energy
  EXPECT_EQ(one, two);
}

TEST(Hdf5Snapshot, RefusesTheFinitePointsetMethod) {
  const World w(RunConfig::from_scene("burgers_upwind"));
  EXPECT_FALSE(hdf5_unsupported(w.params()).empty());
  EXPECT_THROW(hdf5_snapshot(w, IcFormat::Swift), std::runtime_error);
}

}  // namespace
}  // namespace sph
