// Particle store: structure of arrays in double precision. Real particles come first (0..n-1): the
// fluid particles, then the fixed wall particles (kind Wall: they take part in sums but never move).
// Ghost particles (periodic images and wall mirrors) follow and copy their source's state.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sph/fields.h"
#include "sph/vec.h"

namespace sph {

/// What a particle is: fluid moves; a wall particle is fixed and only acts on the fluid.
enum class Kind : std::uint8_t { Fluid = 0, Wall = 1 };

class Particles {
 public:
  Particles() = default;
  /// n real particles in dimension dim, all fluid, with the given scalar fields allocated.
  Particles(int dim, std::size_t n, FieldSet fields);

  int dim() const { return dim_; }
  std::size_t size() const { return n_; }            ///< real particles (fluid + wall)
  std::size_t fluid() const { return n_fluid_; }     ///< fluid particles: indices 0..fluid()-1
  std::size_t total() const { return x[0].size(); }  ///< real + ghosts
  FieldSet fields() const { return fields_; }
  bool has(Field f) const { return fields_.has(f); }
  /// Allocates (zero-filled) the fields of `more` that are not allocated yet.
  void add_fields(FieldSet more);

  /// A scalar field; throws std::logic_error if no stage of the scene allocated it.
  std::vector<double>& operator[](Field f);
  const std::vector<double>& operator[](Field f) const;

  Vec3 pos(std::size_t i) const { return {x[0][i], x[1][i], x[2][i]}; }
  Vec3 vel(std::size_t i) const { return {v[0][i], v[1][i], v[2][i]}; }
  bool is_wall(std::size_t i) const { return kind[i] == static_cast<std::uint8_t>(Kind::Wall); }

  /// Resize to n real + g ghost particles (ghost entries are overwritten by the boundary code).
  void resize_total(std::size_t total);
  /// Reorders the real particles so the fluid comes first and walls last (stable: ids keep their
  /// order within each kind); drops the ghosts. Called once when a scene is built.
  void partition_by_kind();
  /// Reorders the real particles: slot k gets the particle that was at order[k] (every field, id and
  /// kind move with it); ghosts keep their state and follow their sources. `order` must keep the fluid
  /// before the walls.
  void permute(std::span<const std::uint32_t> order);

  std::array<std::vector<double>, 3> x;  ///< position [length]; unused components stay 0
  std::array<std::vector<double>, 3> v;  ///< velocity [length/time]
  std::array<std::vector<double>, 3> a;  ///< acceleration [length/time^2]
  std::vector<std::int64_t> id;          ///< stable particle id (ghosts: id of the source)
  std::vector<std::uint8_t> kind;        ///< Kind of every particle (ghosts: of the source)
  std::vector<std::uint32_t> ghost_src;  ///< for ghost g (index n+g): its real source particle
  std::vector<std::uint8_t> ghost_flip;  ///< for ghost g: bit k set = mirrored across an axis-k wall
  /// for ghost g: x_g[k] = (flipped on k ? -x_src[k] : x_src[k]) + ghost_offset[k][g] [length]
  std::array<std::vector<double>, 3> ghost_offset;

 private:
  int dim_ = 1;
  std::size_t n_ = 0;
  std::size_t n_fluid_ = 0;
  FieldSet fields_;
  std::array<std::vector<double>, kFieldCount> scalar_;
};

}  // namespace sph
