#include "sph/particles.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sph {

Particles::Particles(int dim, std::size_t n, FieldSet fields) : dim_(dim), n_(n), n_fluid_(n), fields_(fields) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("dimension must be 1, 2 or 3");
  resize_total(n);
  for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::int64_t>(i);
}

void Particles::add_fields(FieldSet more) {
  more.for_each([&](Field f) {
    if (fields_.has(f)) return;
    fields_.add(f);
    scalar_[index(f)].assign(total(), 0.0);
  });
}

std::vector<double>& Particles::operator[](Field f) {
  if (!fields_.has(f)) throw std::logic_error("field '" + std::string(info(f).key) + "' is not allocated");
  return scalar_[index(f)];
}

const std::vector<double>& Particles::operator[](Field f) const {
  if (!fields_.has(f)) throw std::logic_error("field '" + std::string(info(f).key) + "' is not allocated");
  return scalar_[index(f)];
}

void Particles::resize_total(std::size_t total) {
  for (auto& c : x) c.resize(total, 0.0);
  for (auto& c : v) c.resize(total, 0.0);
  for (auto& c : a) c.resize(total, 0.0);
  id.resize(total, 0);
  kind.resize(total, static_cast<std::uint8_t>(Kind::Fluid));
  ghost_src.resize(total > n_ ? total - n_ : 0, 0);
  ghost_flip.resize(ghost_src.size(), 0);
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (fields_.has(static_cast<Field>(f))) scalar_[f].resize(total, 0.0);
}

void Particles::partition_by_kind() {
  resize_total(n_);
  std::vector<std::size_t> order(n_);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return !is_wall(i); });
  auto permute = [&](auto& a) {
    auto copy = a;
    for (std::size_t k = 0; k < n_; ++k) a[k] = copy[order[k]];
  };
  for (int k = 0; k < 3; ++k) { permute(x[k]); permute(v[k]); permute(a[k]); }
  permute(id);
  permute(kind);
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (fields_.has(static_cast<Field>(f))) permute(scalar_[f]);
  n_fluid_ = 0;
  while (n_fluid_ < n_ && !is_wall(n_fluid_)) ++n_fluid_;
}

}  // namespace sph
