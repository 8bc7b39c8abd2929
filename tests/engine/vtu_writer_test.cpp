// ParaView's XML formats (sph/vtu_writer.h): the appended binary blocks decode to the particles' values
// in id order, every allocated field is there under its key, and the .pvd lists the series.
#include "sph/vtu_writer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace sph {
namespace {

/// The raw block of a named DataArray (after its UInt64 byte count), from the appended section. (Plain
/// searches, not <regex>: GCC 12 warns falsely inside <regex> under -fsanitize=address.)
std::string block(const std::string& vtu, const std::string& name) {
  const std::size_t tag = vtu.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t end = vtu.find('>', tag);
  const std::size_t off = vtu.find("offset=\"", tag);
  if (off == std::string::npos || off > end) return {};
  const std::size_t offset = std::stoull(vtu.substr(off + 8));
  const std::size_t base = vtu.find("<AppendedData encoding=\"raw\">");
  const std::size_t start = vtu.find('_', base) + 1 + offset;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, vtu.data() + start, sizeof bytes);
  return vtu.substr(start + sizeof bytes, bytes);
}

template <class T>
std::vector<T> values(const std::string& raw) {
  std::vector<T> v(raw.size() / sizeof(T));
  std::memcpy(v.data(), raw.data(), v.size() * sizeof(T));
  return v;
}

TEST(VtuWriter, BlocksDecodeToTheParticlesInIdOrder) {
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank");  // 2D, with wall particles
  cfg.set("scene.dx", "0.1", "test");
  World world(cfg);
  world.step();
  const std::string vtu = vtu_file(world);
  const Particles& p = world.particles();
  const auto& order = world.by_id();
  EXPECT_NE(vtu.find("NumberOfPoints=\"" + std::to_string(p.size()) + "\""), std::string::npos);
  EXPECT_NE(vtu.find("header_type=\"UInt64\""), std::string::npos);

  const std::vector<double> points = values<double>(block(vtu, "Points"));
  const std::vector<double> vel = values<double>(block(vtu, "velocity"));
  const std::vector<std::int64_t> ids = values<std::int64_t>(block(vtu, "id"));
  const std::vector<std::uint8_t> kind = values<std::uint8_t>(block(vtu, "kind"));
  ASSERT_EQ(points.size(), 3 * p.size());
  ASSERT_EQ(vel.size(), 3 * p.size());
  ASSERT_EQ(ids.size(), p.size());
  std::size_t walls = 0;
  for (std::size_t r = 0; r < p.size(); ++r) {
    const std::uint32_t i = order[r];
    EXPECT_EQ(ids[r], p.id[i]);
    EXPECT_EQ(kind[r], p.kind[i]);
    walls += kind[r];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(points[3 * r + k], p.x[k][i]);
      EXPECT_EQ(vel[3 * r + k], p.v[k][i]);
    }
  }
  EXPECT_EQ(walls, p.size() - p.fluid());
  int fields = 0;
  p.fields().for_each([&](Field f) {
    const std::vector<double> v = values<double>(block(vtu, std::string(info(f).key)));
    ASSERT_EQ(v.size(), p.size()) << info(f).key;
    for (std::size_t r = 0; r < p.size(); ++r) EXPECT_EQ(v[r], p[f][order[r]]) << info(f).key;
    ++fields;
  });
  EXPECT_GE(fields, 5);  // m, rho, h, p, drhodt at least
}

TEST(VtuWriter, CollectionListsEveryFileWithItsTime) {
  const std::string pvd = pvd_file({{0.0, "a.vtu"}, {0.1, "b.vtu"}});
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"a.vtu\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0.10000000000000001\""), std::string::npos);  // the exact double
}

}  // namespace
}  // namespace sph
