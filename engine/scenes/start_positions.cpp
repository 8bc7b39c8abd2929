#include "start_positions.h"

#include <cstdint>

#include "glass.h"

namespace sph::scenes {

std::vector<SceneParam> start_params(double n_side) {
  return {{"n_side", n_side, 8, 4000, true, "particles per unit length (about n_side^2 in the box)", "count"},
          {"start", 0, 0, 1, true, "initial positions: 0 hexagonal close-packed lattice, 1 glass", "dimensionless"},
          {"seed", 1, 0, 1e15, true, "random seed of the glass (scene.start = 1)", "dimensionless"}};
}

Lattice start_positions(int dim, const Vec3& lo, const Vec3& hi, const SceneValues& v) {
  const double spacing = 1.0 / v.at("n_side");
  if (v.at("start") == 0) return close_packed(dim, lo, hi, spacing);
  return {glass_fill(dim, lo, hi, spacing, static_cast<std::uint64_t>(v.at("seed"))), spacing};
}

}  // namespace sph::scenes
