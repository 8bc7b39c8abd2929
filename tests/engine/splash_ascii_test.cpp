// SPLASH's ascii layout (sph/splash_ascii.h): the time where SPLASH reads it, gamma in (1, 2], the
// "[NN label]" line with the labels SPLASH recognises, and one row per particle in id order.
#include "sph/splash_ascii.h"

#include <gtest/gtest.h>

#include <sstream>

namespace sph {
namespace {

TEST(SplashAscii, HeaderAndRowsAsSplashReadsThem) {
  RunConfig cfg = RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "50", "test");
  World world(cfg);
  world.advance_to(0.01);
  std::istringstream in(splash_ascii_file(world));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# sph-sandbox particles for SPLASH: scene sod", 0), 0u);
  std::getline(in, line);  // the first numeric header line with a decimal point: the time
  EXPECT_DOUBLE_EQ(std::stod(line.substr(1)), world.time());
  EXPECT_NE(line.find('.'), std::string::npos);
  std::getline(in, line);  // gamma, in (1, 2]
  EXPECT_DOUBLE_EQ(std::stod(line.substr(1)), 1.4);
  std::getline(in, line);
  EXPECT_NE(line.find("[01                x]"), std::string::npos);
  EXPECT_NE(line.find("[02               vx]"), std::string::npos);
  for (const char* label : {"m]", "rho]", "h]", "u]", "p]"}) EXPECT_NE(line.find(label), std::string::npos) << label;
  EXPECT_EQ(line.find("itype"), std::string::npos);  // no walls, no type column
  const Particles& p = world.particles();
  std::size_t rows = 0;
  for (; std::getline(in, line); ++rows) {
    std::istringstream cols(line);
    double x = 0, vx = 0, m = 0, rho = 0;
    cols >> x >> vx >> m >> rho;
    const std::uint32_t i = world.by_id()[rows];
    EXPECT_DOUBLE_EQ(x, p.x[0][i]);
    EXPECT_DOUBLE_EQ(vx, p.v[0][i]);
    EXPECT_DOUBLE_EQ(m, p[Field::Mass][i]);
    EXPECT_DOUBLE_EQ(rho, p[Field::Density][i]);
  }
  EXPECT_EQ(rows, p.size());
}

TEST(SplashAscii, WallsGetSplashsTypeColumn) {
  RunConfig cfg = RunConfig::from_scene("hydrostatic_tank");
  cfg.set("scene.dx", "0.1", "test");
  World world(cfg);
  const std::string text = splash_ascii_file(world);
  EXPECT_NE(text.find("itype]"), std::string::npos);
  EXPECT_NE(text.find("[01                x] [02                y] [03               vx]"), std::string::npos);
  std::size_t twos = 0;
  for (std::size_t k = text.find("  2\n"); k != std::string::npos; k = text.find("  2\n", k + 1)) ++twos;
  EXPECT_EQ(twos, world.particles().size() - world.particles().fluid());
}

}  // namespace
}  // namespace sph
