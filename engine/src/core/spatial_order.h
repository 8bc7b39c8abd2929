// Spatial ordering of the particle arrays (tests/engine/spatial_order_test.cpp): particles close in
// space are stored close in memory, so the pair loops gather their neighbours from a few cache lines
// instead of from all over the arrays. The order is a Morton (Z-order) curve over cells of a given
// size.
#pragma once
#include <cstdint>
#include <vector>

#include "sph/particles.h"

namespace sph {

/// Indices begin..end-1 of `p` in Morton order of their cell (cells of side `cell` [length]); ties (the
/// same cell) keep their current order, so the result depends only on the state, never on threads.
std::vector<std::uint32_t> morton_order(const Particles& p, std::size_t begin, std::size_t end, double cell);

/// The Morton key of integer cell coordinates c (each < 2^min(32, 63/dim)): their bits interleaved.
std::uint64_t morton_key(const std::uint32_t c[3], int dim);

}  // namespace sph
