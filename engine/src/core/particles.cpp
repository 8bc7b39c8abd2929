#include "sph/particles.h"

#include <stdexcept>
#include <string>

namespace sph {

Particles::Particles(int dim, std::size_t n, FieldSet fields) : dim_(dim), n_(n), fields_(fields) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("dimension must be 1, 2 or 3");
  resize_total(n);
  for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::int64_t>(i);
}

std::vector<double>& Particles::operator[](Field f) {
  if (!fields_.has(f)) throw std::logic_error("field '" + std::string(info(f).key) + "' is not allocated");
  return scalar_[static_cast<std::size_t>(f)];
}

const std::vector<double>& Particles::operator[](Field f) const {
  if (!fields_.has(f)) throw std::logic_error("field '" + std::string(info(f).key) + "' is not allocated");
  return scalar_[static_cast<std::size_t>(f)];
}

void Particles::resize_total(std::size_t total) {
  for (auto& c : x) c.resize(total, 0.0);
  for (auto& c : v) c.resize(total, 0.0);
  for (auto& c : a) c.resize(total, 0.0);
  id.resize(total, 0);
  ghost_src.resize(total > n_ ? total - n_ : 0, 0);
  ghost_flip.resize(ghost_src.size(), 0);
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (fields_.has(static_cast<Field>(f))) scalar_[f].resize(total, 0.0);
}

}  // namespace sph
