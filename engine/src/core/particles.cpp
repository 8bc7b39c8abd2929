#include "sph/particles.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/parallel.h"

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
  for (auto& o : ghost_offset) o.resize(ghost_src.size(), 0.0);
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (fields_.has(static_cast<Field>(f))) scalar_[f].resize(total, 0.0);
}

void Particles::partition_by_kind() {
  std::vector<std::uint32_t> order(n_);
  resize_total(n_);  // no ghosts yet
  std::iota(order.begin(), order.end(), 0u);
  std::stable_partition(order.begin(), order.end(), [&](std::uint32_t i) { return !is_wall(i); });
  permute(order);
  n_fluid_ = 0;
  while (n_fluid_ < n_ && !is_wall(n_fluid_)) ++n_fluid_;
}

void Particles::permute(std::span<const std::uint32_t> order) {
  if (order.size() != n_) throw std::invalid_argument("a permutation must cover every real particle");
  std::vector<double> scratch;
  const std::size_t n = n_;
  // a gather per array: the same result for any team (a team pays off from kParallelMin particles)
  auto apply = [&](auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    if constexpr (std::is_same_v<T, double>) {
      scratch.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n));
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
      for (std::size_t k = 0; k < n; ++k) a[k] = scratch[order[k]];
    } else {
      const std::vector<T> copy(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n));
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
      for (std::size_t k = 0; k < n; ++k) a[k] = copy[order[k]];
    }
  };
  for (int k = 0; k < 3; ++k) { apply(x[k]); apply(v[k]); apply(a[k]); }
  apply(id);
  apply(kind);
  for (std::size_t f = 0; f < kFieldCount; ++f)
    if (fields_.has(static_cast<Field>(f))) apply(scalar_[f]);
  // ghosts stay where they are (their state is unchanged); their sources moved
  std::vector<std::uint32_t> slot(n_);
  for (std::size_t k = 0; k < n_; ++k) slot[order[k]] = static_cast<std::uint32_t>(k);
  for (auto& src : ghost_src) src = slot[src];
}

}  // namespace sph
