// HDF5 initial conditions (sph/hdf5_ic.h, sph/ic_export.h): a scene exported in the SWIFT or GADGET-4
// layout and read back starts from the same state and evolves the same; files this code cannot run are
// refused by name; a SWIFT-style IC runs as a periodic ideal gas.
#include "sph/hdf5_ic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <unistd.h>

#include "io/hdf5_util.h"
#include "sph/ic_export.h"
#include "sph/world.h"

namespace sph {
namespace {

namespace fs = std::filesystem;

std::string temp_path(const std::string& name) {
  return (fs::temp_directory_path() / ("sph_hdf5_ic_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string write_bytes(const std::string& name, const std::string& bytes) {
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(1.0, std::max(std::abs(a), std::abs(b))); }

/// Largest relative difference of positions, velocities and every field both worlds have, by id, rates
/// aside: the conduction's signal speed sqrt(|P_a - P_b| / rho) turns a round-off difference of 1e-16 in P
/// between equal states into 1e-8 in du/dt, so rates are compared through the states they lead to.
double state_difference(const World& a, const World& b) {
  const Particles& p = a.particles();
  const Particles& q = b.particles();
  EXPECT_EQ(p.size(), q.size());
  EXPECT_EQ(p.fluid(), q.fluid());
  double worst = 0.0;
  for (std::size_t r = 0; r < std::min(p.size(), q.size()); ++r) {
    const std::uint32_t i = a.by_id()[r], j = b.by_id()[r];
    EXPECT_EQ(p.id[i], q.id[j]);
    EXPECT_EQ(p.kind[i], q.kind[j]);
    for (int k = 0; k < 3; ++k) worst = std::max({worst, rel(p.x[k][i], q.x[k][j]), rel(p.v[k][i], q.v[k][j])});
    p.fields().for_each([&](Field f) {
      if (q.has(f) && f != Field::HIterations && f != Field::EnergyRate && f != Field::DensityRate)
        worst = std::max(worst, rel(p[f][i], q[f][j]));
    });
  }
  return worst;
}

struct Case {
  const char* scene;
  std::vector<std::pair<const char*, const char*>> sets;
};

class RoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(RoundTrip, ExportedICStartsAndStepsLikeTheScene) {
  RunConfig cfg = RunConfig::from_scene(GetParam().scene);
  for (const auto& [k, v] : GetParam().sets) cfg.set(k, v, "test");
  for (IcFormat format : {IcFormat::Swift, IcFormat::Gadget4}) {
    World a(cfg);
    const std::string path = write_bytes(std::string(GetParam().scene) + to_string(format) + ".hdf5",
                                         hdf5_snapshot(a, format));
    const RunConfig back = load_hdf5_ic(path);
    EXPECT_EQ(back.params, cfg.params) << "the scene's physics and parameters come back";
    EXPECT_EQ(back.scene->dim, cfg.scene->dim);
    EXPECT_EQ(back.scene->units.length_cgs, cfg.scene->units.length_cgs);
    World b(back);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(b.domain().bc[k], a.domain().bc[k]);
      EXPECT_EQ(b.domain().lo[k], a.domain().lo[k]);
      EXPECT_EQ(b.domain().hi[k], a.domain().hi[k]);
    }
    EXPECT_EQ(b.report().has_reference(), a.report().has_reference());
    EXPECT_LT(state_difference(a, b), 1e-12) << to_string(format) << ": the initial state";
    for (int s = 0; s < 5; ++s) {
      a.step();
      b.step();
    }
    // the initial states' round-off (checked above to 1e-12) grows through the conduction's
    // sqrt(|P_a - P_b|) and the h solve's stopping test (tolerance 1e-6): 1.1e-7 on Sod after five steps
    EXPECT_LT(state_difference(a, b), 1e-6) << to_string(format) << ": five steps later";
    if (a.report().has_reference()) {
      const std::vector<double> ra = a.report().reference_values(), rb = b.report().reference_values();
      for (std::size_t k = 0; k < ra.size(); ++k)
        if (std::isfinite(ra[k])) {
          EXPECT_LT(rel(ra[k], rb[k]), 1e-6) << a.report().reference_columns()[k].name;
        }
    }
    fs::remove(path);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, RoundTrip,
    ::testing::Values(Case{"sod", {{"scene.n_left", "60"}}},                        // 1D gas, mirror walls, reference
                      Case{"box_random", {{"scene.count", "300"}}},                 // 2D periodic gas
                      Case{"hydrostatic_tank", {{"scene.dx", "0.1"}}},              // liquid, wall particles, SI units
                      Case{"kepler", {}},                                           // N-body: PartType1
                      Case{"sedov3d", {{"scene.n_side", "8"}}}),                         // 3D blast
    [](const auto& info) { return std::string(info.param.scene); });

/// A file written with the helpers, for the refusals.
class BadFile {
 public:
  BadFile() : file_(h5::create_memory_file()) {}
  hid_t root() const { return file_.get(); }
  std::string save(const std::string& name) { return write_bytes(name, h5::file_bytes(file_.get())); }

 private:
  h5::Handle file_;
};

/// A small valid 1D gas IC (n particles on [0, 1)), for variations.
void gas_ic(hid_t root, std::size_t n, std::vector<long long> counts = {}) {
  h5::Handle header = h5::create_group(root, "Header");
  if (counts.empty()) counts = {static_cast<long long>(n), 0, 0, 0, 0, 0};
  h5::write_attr_ints(header.get(), "NumPart_ThisFile", counts, H5T_STD_U32LE);
  h5::write_attr(header.get(), "BoxSize", 1.0);
  h5::write_attr_int(header.get(), "Dimension", 1);
  h5::Handle part = h5::create_group(root, "PartType0");
  std::vector<double> x(3 * n, 0.0), v(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) x[3 * i] = (i + 0.5) / static_cast<double>(n);
  h5::write_dataset(part.get(), "Coordinates", x, 3);
  h5::write_dataset(part.get(), "Velocities", v, 3);
  h5::write_dataset(part.get(), "Masses", std::vector<double>(n, 1.0 / static_cast<double>(n)), 1);
  h5::write_dataset(part.get(), "InternalEnergy", std::vector<double>(n, 1.5), 1);
}

void expect_refused(const std::string& path, const std::string& words) {
  try {
    load_hdf5_ic(path);
    ADD_FAILURE() << path << " was accepted";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << "names the file: " << msg;
    EXPECT_NE(msg.find(words), std::string::npos) << msg;
  }
  std::error_code ec;  // some paths cannot even be named
  fs::remove(path, ec);
}

/// A file made by `build`, which load_hdf5_ic must refuse with `words` in the message.
void expect_refused(const std::string& name, const std::function<void(hid_t)>& build, const std::string& words) {
  BadFile f;
  build(f.root());
  expect_refused(f.save(name), words);
}

/// The gas IC of n particles with one of its /PartType0 datasets replaced (cols > 0) or removed (values empty).
std::function<void(hid_t)> gas_ic_changing(std::size_t n, const char* name, std::vector<double> values, std::size_t cols) {
  return [=](hid_t root) {
    gas_ic(root, n);
    h5::Handle part = h5::open_group(root, "PartType0");
    H5Ldelete(part.get(), name, H5P_DEFAULT);
    if (!values.empty()) h5::write_dataset(part.get(), name, values, cols);
  };
}

/// The gas IC with one more /Header attribute.
std::function<void(hid_t)> gas_ic_with(const char* attr, double value) {
  return [attr, value](hid_t root) {
    gas_ic(root, 10);
    h5::Handle header = h5::open_group(root, "Header");
    h5::write_attr(header.get(), attr, value);
  };
}

TEST(Hdf5Ic, RefusesWhatItCannotRun) {
  const std::string text = temp_path("text.hdf5");
  std::ofstream(text) << "not hdf5";
  expect_refused(text, "not an HDF5 file");
  expect_refused(temp_path("missing.hdf5"), "no such file");
  // a name the system refuses (longer than NAME_MAX): an input error, not an uncaught filesystem_error
  // (the scene-file fuzzer found it: tests/fuzz/corpus/scene_json/regression_hdf5_name_too_long)
  expect_refused(std::string(300, 'L') + ".hdf5", "cannot be read (File name too long)");
  expect_refused("noheader.hdf5", [](hid_t root) { h5::create_group(root, "Other"); }, "no /Header group");
  expect_refused("entropy.hdf5", gas_ic_with("Flag_Entropy_ICs", 1), "Flag_Entropy_ICs = 1");
  expect_refused("split.hdf5", gas_ic_with("NumFilesPerSnapshot", 4), "split over 4 files");
  expect_refused("cosmo.hdf5", gas_ic_with("Redshift", 49), "comoving integration");
  expect_refused("mixed.hdf5", [](hid_t root) { gas_ic(root, 10, {10, 5, 0, 0, 0, 0}); }, "PartType0 (10) PartType1 (5)");
  expect_refused("rows.hdf5", [](hid_t root) { gas_ic(root, 10, {12, 0, 0, 0, 0, 0}); },
                 "Coordinates has 10 rows for 12 particles");
  expect_refused("dimension.hdf5", gas_ic_changing(4, "Coordinates", std::vector<double>(12, 0.25), 3),
                 "Dimension = 1 but particle 0 has y = 0.25");
  expect_refused("mass.hdf5", gas_ic_changing(3, "Masses", {1.0, -1.0, 1.0}, 1), "Masses of particle 1 is -1");
  expect_refused("nou.hdf5", gas_ic_changing(4, "InternalEnergy", {}, 1), "/PartType0/InternalEnergy is missing");
}

TEST(Hdf5Ic, AForeignGasICRunsInItsPeriodicBox) {
  BadFile f;
  gas_ic(f.root(), 64);
  const std::string path = f.save("foreign.hdf5");
  RunConfig cfg = load_hdf5_ic(path);
  EXPECT_EQ(cfg.scene->dim, 1);
  EXPECT_DOUBLE_EQ(cfg.params.gas.gamma, 5.0 / 3.0);  // SWIFT's default
  EXPECT_EQ(cfg.values.at("periodic"), 1.0);
  World w(cfg);
  EXPECT_EQ(w.domain().bc[0], Boundary::Periodic);
  EXPECT_DOUBLE_EQ(w.domain().hi[0], 1.0);
  const Particles& p = w.particles();
  for (std::size_t i = 0; i < p.fluid(); ++i) {  // a uniform periodic lattice: rho = N m / L everywhere
    EXPECT_NEAR(p[Field::Density][i], 1.0, 2e-3);
    EXPECT_NEAR(p[Field::Pressure][i], (5.0 / 3.0 - 1.0) * p[Field::Density][i] * 1.5, 1e-12);
  }
  cfg.set("scene.periodic", "0", "test");
  World open(cfg);
  EXPECT_EQ(open.domain().bc[0], Boundary::Open);
  fs::remove(path);
}

TEST(Hdf5Ic, ForeignNBodyParticlesTakeTheMassTableAndGOfTheirUnits) {
  for (const bool with_units : {false, true}) {
    BadFile f;
    h5::Handle header = h5::create_group(f.root(), "Header");
    h5::write_attr_ints(header.get(), "NumPart_ThisFile", {0, 3, 0, 0, 0, 0}, H5T_STD_U32LE);
    h5::write_attr(header.get(), "MassTable", std::vector<double>{0.0, 0.25, 0, 0, 0, 0});
    h5::Handle part = h5::create_group(f.root(), "PartType1");
    h5::write_dataset(part.get(), "Coordinates", std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 1}, 3);
    h5::write_dataset(part.get(), "Velocities", std::vector<double>(9, 0.0), 3);
    if (with_units) {  // AU, solar mass, year: G = 4 pi^2 to 1e-3 (CODATA G, IAU masses)
      h5::Handle units = h5::create_group(f.root(), "Units");
      h5::write_attr(units.get(), "Unit length in cgs (U_L)", 1.495978707e13);
      h5::write_attr(units.get(), "Unit mass in cgs (U_M)", 1.98847e33);
      h5::write_attr(units.get(), "Unit time in cgs (U_t)", 3.15576e7);
    }
    const std::string path = f.save(with_units ? "nbody_units.hdf5" : "nbody.hdf5");
    const RunConfig cfg = load_hdf5_ic(path);
    EXPECT_EQ(cfg.params.physics.gravity, GravityType::Direct);
    EXPECT_EQ(cfg.params.physics.density, DensityMode::None);
    EXPECT_NEAR(cfg.params.gravity.G, with_units ? 4.0 * std::numbers::pi * std::numbers::pi : 1.0, with_units ? 0.04 : 0.0);
    const World w(cfg);
    ASSERT_EQ(w.particles().size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(w.particles()[Field::Mass][i], 0.25);
    fs::remove(path);
  }
}

}  // namespace
}  // namespace sph
