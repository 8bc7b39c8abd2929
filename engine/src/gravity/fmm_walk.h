// The state of one thread's walk of the fast multipole method (gravity/fmm.cpp, fmm_leaf.cpp).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "gravity/fmm.h"

namespace sph::gravity {

/// A thread's state: per depth, the cells still to test and those passed on.
struct FastMultipole::Walk {
  const PairLaw* law = nullptr;
  const Criterion* crit = nullptr;
  double e2 = 0.0;  ///< Plummer eps^2 of the expansions (0 with kernel softening)
  Result* out = nullptr;
  /// per depth (sized once: a caller's list must not move while its children are walked); the tree is
  /// at most 61 levels deep (barnes_hut_build.cpp)
  std::vector<std::vector<std::uint32_t>> todo = std::vector<std::vector<std::uint32_t>>(64),
                                          keep = std::vector<std::vector<std::uint32_t>>(64);
  std::vector<std::uint32_t> far;                  ///< the cells a sink takes as multipoles, in list order
  std::vector<std::uint32_t> direct;               ///< the cells a sink leaf's particles take one by one
  std::vector<double> ax, ay, az, phi, re2, mmax;  ///< a leaf's sums
  /// Only the sinks (FastMultipole::live_, sink_): subtrees without one are skipped, a leaf's sinks gathered.
  bool live = false;
  std::vector<std::uint32_t> slot;       ///< a leaf's sinks: their index in the leaf
  std::vector<std::ptrdiff_t> local;     ///< a leaf particle's index among its sinks, -1 if none
  std::array<std::vector<double>, 3> sx;  ///< the sinks' positions
  Counts counts;
  /// Subtrees left for the parallel pass: their root and its list.
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>>* deferred = nullptr;
};

}  // namespace sph::gravity
