// Particle store: structure of arrays in double precision. Real particles come first (0..n-1);
// ghost particles (periodic images and wall mirrors) follow and copy their source's state.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "sph/fields.h"
#include "sph/vec.h"

namespace sph {

class Particles {
 public:
  Particles() = default;
  /// n real particles in dimension dim, with the given scalar fields allocated.
  Particles(int dim, std::size_t n, FieldSet fields);

  int dim() const { return dim_; }
  std::size_t size() const { return n_; }            ///< real particles
  std::size_t total() const { return x[0].size(); }  ///< real + ghosts
  FieldSet fields() const { return fields_; }
  bool has(Field f) const { return fields_.has(f); }

  /// A scalar field; throws std::logic_error if the scene did not allocate it.
  std::vector<double>& operator[](Field f);
  const std::vector<double>& operator[](Field f) const;

  Vec3 pos(std::size_t i) const { return {x[0][i], x[1][i], x[2][i]}; }
  Vec3 vel(std::size_t i) const { return {v[0][i], v[1][i], v[2][i]}; }

  /// Resize to n real + g ghost particles (ghost entries are overwritten by the boundary code).
  void resize_total(std::size_t total);

  std::array<std::vector<double>, 3> x;  ///< position [length]; unused components stay 0
  std::array<std::vector<double>, 3> v;  ///< velocity [length/time]
  std::array<std::vector<double>, 3> a;  ///< acceleration [length/time^2]
  std::vector<std::int64_t> id;          ///< stable particle id (ghosts: id of the source)
  std::vector<std::uint32_t> ghost_src;  ///< for ghost g (index n+g): its real source particle
  std::vector<std::uint8_t> ghost_flip;  ///< for ghost g: bit k set = velocity component k mirrored

 private:
  int dim_ = 1;
  std::size_t n_ = 0;
  FieldSet fields_;
  std::array<std::vector<double>, kFieldCount> scalar_;
};

}  // namespace sph
