// SPLASH's ascii reader (read_data_ascii.f90, v3.6): header lines start with '#'; the first numeric
// header line with a decimal point is the time; a later one in (1, 2] is gamma; the labels line
// "# [01 x] [02 y] ..." names the columns, which SPLASH matches to x/y/z, vx.., m, rho, h, u, p, itype.
#include "sph/splash_ascii.h"

#include <cstdio>

namespace sph {

std::string splash_ascii_file(const World& world) {
  const Particles& p = world.particles();
  const int dim = p.dim();
  const char* axes[] = {"x", "y", "z"};
  const char* vel[] = {"vx", "vy", "vz"};
  std::vector<Field> fields;
  for (Field f : {Field::Mass, Field::Density, Field::H, Field::Energy, Field::Pressure, Field::Potential})
    if (p.has(f)) fields.push_back(f);
  const bool walls = p.fluid() < p.size();

  char buf[64];
  std::string out = "# sph-sandbox particles for SPLASH: scene " + world.config().scene->name + ", step " +
                    std::to_string(world.steps()) + ", " + std::to_string(p.size()) + " particles\n";
  std::snprintf(buf, sizeof buf, "# %.16e\n", world.time());  // always has a '.': SPLASH's time
  out += buf;
  if (world.params().physics.eos == EosType::IdealGas && world.params().gas.gamma > 1.0 &&
      world.params().gas.gamma <= 2.0) {
    std::snprintf(buf, sizeof buf, "# %.16e\n", world.params().gas.gamma);  // SPLASH's gamma: in (1, 2]
    out += buf;
  }
  std::string labels = "#";
  int column = 0;
  auto label = [&](std::string_view name) {
    std::snprintf(buf, sizeof buf, " [%02d %16s]", ++column, std::string(name).c_str());
    labels += buf;
  };
  for (int k = 0; k < dim; ++k) label(axes[k]);
  for (int k = 0; k < dim; ++k) label(vel[k]);
  for (Field f : fields) label(info(f).key);
  if (walls) label("itype");
  out += labels + "\n";

  for (const std::uint32_t i : world.by_id()) {
    std::string row;
    auto put = [&](double v) {
      std::snprintf(buf, sizeof buf, " %23.16e", v);
      row += buf;
    };
    for (int k = 0; k < dim; ++k) put(p.x[k][i]);
    for (int k = 0; k < dim; ++k) put(p.v[k][i]);
    for (Field f : fields) put(p[f][i]);
    if (walls) row += p.is_wall(i) ? "  2" : "  1";
    out += row + "\n";
  }
  return out;
}

}  // namespace sph
