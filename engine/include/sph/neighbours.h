// Neighbour search: particles sorted into cells (a counting sort, the array form of the head/next cell
// linked list of seed 002 §3.2), then a gather per particle in a fixed order, so lists are identical for
// any thread count.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sph/particles.h"

namespace sph {

/// Compressed neighbour lists of the real particles: neighbours of i are index[offset[i] .. offset[i+1]).
/// Each list includes i itself and is in a deterministic order (cell by cell, index order inside a cell).
struct NeighbourWorkspace;  ///< cell grid and per-thread buffers, kept between builds (no page faults)

struct NeighbourList {
  std::vector<std::uint32_t> offset;
  std::vector<std::uint32_t> index;
  std::shared_ptr<NeighbourWorkspace> work;  ///< reused by build_neighbours; created on first use
  std::span<const std::uint32_t> of(std::size_t i) const {
    return {index.data() + offset[i], index.data() + offset[i + 1]};
  }
  std::size_t pairs() const { return index.size(); }
};

/// All j (real or ghost) with |r_i - r_j| < radius * max(h_i, h_j), for every real i. `h` covers all
/// particles (ghosts included).
void build_neighbours(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out);

/// build_neighbours in two parts, for lists gathered only for the particles that need them (individual
/// time steps). First the grid of the particles as they are now (kept in out.work), every list empty:
void build_neighbour_grid(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out);
/// then the lists of `rows` (increasing, each still empty), exactly as build_neighbours would have given
/// them when the grid was built: x holds the real particles' positions then. The lists already there
/// keep their content; the rows are merged in index order, so the result is the same for any thread count.
void gather_neighbour_rows(const std::array<std::vector<double>, 3>& x, const std::vector<double>& h, double radius,
                           std::span<const std::uint32_t> rows, NeighbourList& out);

/// The entries of `wide` (lists built with a larger radius) with |r_i - r_j| < radius * max(h_i, h_j),
/// each list in its order, into `out`: what build_neighbours(p, h, radius) finds, once every pair within
/// `radius` is in `wide` (Verlet lists). Self-pairs are kept.
void filter_neighbours(const Particles& p, const std::vector<double>& h, double radius, const NeighbourList& wide,
                       NeighbourList& out);

/// The lists after the real particles were reordered (slot k holds the particle that was at order[k];
/// ghosts, at index >= order.size(), stay): the same pairs, renumbered, each list in its old order.
void permute_neighbours(NeighbourList& nl, std::span<const std::uint32_t> order);

/// Same result by brute force, O(N^2): the reference the tests compare against.
void build_neighbours_brute(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out);

}  // namespace sph
