// The fast multipole method of self-gravity (physics.gravity = fmm; Greengard & Rokhlin 1987, in the
// Cartesian form of Dehnen 2002, J. Comput. Phys. 179, 27): the Barnes-Hut octree's cells carry
// multipoles to order P about their centres of mass (gravity/expansion.h), and a dual walk gives every
// sink cell B a local expansion (cell-cell, multipole-to-local) from the cells A it is well separated
// from; a sink leaf takes a cell it is not separated from at each of its particles (multipole to
// particle) when the cell is small enough for that, and sums pair by pair with the leaves left.
//
// - Order P = 5 by default (gravity.fmm_order; fmm.cpp says why), leaves of at most 32 particles.
// - Opening criterion (Dehnen 2002 eq. 12, with the centres of mass as expansion centres): A and B
//   interact as cells when R > (r_A + r_B) / theta, R = |z_A - z_B|, r the cell's bmax; and, the
//   relative guard, when the expansion's error estimate M_A rho^P / (R^2 (1 - rho)^2), rho =
//   (r_A + r_B)/R, is at most tol times the smallest |a| in B, |a| taken from a first walk at theta = 1
//   (a coarse one: the result depends on the positions only). The (1 - rho)^-2 keeps pairs near the
//   series' radius of convergence out: without it the guard at theta = 1 left 1.2e-1 largest errors. With kernel softening, also R - r_A - r_B > S max(h_A, h_B): every
//   pair is beyond both supports, where the law is Newton's. Multipole to particle: the same test with
//   r_B = 0 at the distance R - r_B of B's nearest possible particle. Without it a large sink leaf (the
//   sparse outskirts of a Plummer sphere) took thousands of small cells each just within the guard, and
//   their errors, all of one sign, added up: RMS 1.6e-3 at N = 2e4 instead of 7.6e-5.
// - One-sided (a gather): a sink cell's expansion and its particles' sums are written only by the walk
//   of that cell, which starts from its parent's list of cells not yet accounted for; subtrees are
//   walked in parallel. The sums run in list order, so the result is bitwise the same for any thread
//   count. Leaf-leaf sums run over the sink's particles in the inner loop (vectorised across sinks, each
//   lane one particle's sum in source order): the same bits for any vector width.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "gravity/barnes_hut.h"
#include "gravity/expansion.h"
#include "gravity/softening.h"
#include "gravity/sources.h"

namespace sph::gravity {

class FastMultipole {
 public:
  static constexpr int kDefaultOrder = 5;
  static constexpr std::uint32_t kLeafSize = 32;
  explicit FastMultipole(int order = kDefaultOrder) : ex_(make_expansion(order)) {}
  int order() const { return ex_->order(); }
  /// Builds the tree of particles 0..s.n-1 and its multipoles.
  void build(const Sources& s, std::uint32_t leaf_size = kLeafSize);
  /// Accelerations and potentials of every particle at opening angle theta (0 < theta <= 1) with the
  /// relative guard at tolerance tol (0: none). With sinks named (s.active, Result::begin) only theirs:
  /// sink cells holding none are not walked, and each sink's result has the bits of a full evaluation.
  void evaluate(const Sources& s, const PairLaw& law, double G, double theta, Result& out,
                double tol = BarnesHutTree::kDefaultTol) const;

  struct Counts {
    std::size_t m2l = 0, pairs = 0;
  };

 private:
  struct Walk;
  struct Criterion {
    double inv_theta = 0.0, support = 0.0, tol = 0.0;
    bool kernel = false;
    const std::vector<double>* amin = nullptr;  ///< smallest |a| of each node (the guard); none: no guard
    int order = 1;                              ///< the expansion's order P
  };
  /// The opening criterion of a source of mass `mass` and size rs at squared distance R2 (see above).
  bool accepts(const Criterion& c, double mass, double rs, double R2, double hmax, std::uint32_t node_b) const;
  /// Cells A and B interact as expansions (M2L).
  bool separated(const Criterion& c, const TreeNode& a, const TreeNode& b, std::uint32_t node_b) const;
  /// A's multipoles are accurate at every particle of B (M2P: the criterion with r_B = 0 and R - r_B).
  bool reaches_particles(const Criterion& c, const TreeNode& a, const TreeNode& b, std::uint32_t node_b) const;
  /// One walk for every particle (for the sinks only: sinks_only, live_), results per unit G in tree order.
  void walk(const PairLaw& law, const Criterion& c, Result& out, bool sinks_only = false) const;
  /// sink_ and live_ from the flags of s.active (storage order).
  void mark_sinks(const std::uint8_t* active) const;
  /// Sink node b: M2L from the cells of `near` it is separated from; passes the rest to its children
  /// (internal) or sums them pair by pair (leaf).
  void visit(std::uint32_t b, const std::vector<std::uint32_t>& near, Walk& w, std::size_t depth) const;
  /// L_b += the M2L of the cells w.far (in groups of four, Expansion::m2l4).
  void far_field(std::uint32_t b, Walk& w) const;
  void leaf(std::uint32_t b, const std::vector<std::uint32_t>& near, Walk& w) const;
  const double* M(std::uint32_t node) const { return &M_[node * ex_->size()]; }
  double* L(std::uint32_t node) const { return &L_[node * ex_->size()]; }
  /// positions, masses and h in tree order, kept by the tree
  const std::array<std::vector<double>, 3>& tx() const { return tree_.sorted_x(); }
  const std::vector<double>& tm() const { return tree_.sorted_m(); }
  const std::vector<double>& th() const { return tree_.sorted_h(); }

  std::unique_ptr<Expansion> ex_;
  BarnesHutTree tree_;
  std::vector<double> M_;                  ///< multipoles, size() per node
  mutable std::vector<double> L_;          ///< local expansions, size() per node
  mutable std::vector<double> amin_;       ///< smallest |a| estimate per node (the guard)
  mutable Result walked_;
  mutable std::vector<std::uint8_t> sink_;   ///< 1 for a sink, in tree order (individual time steps)
  mutable std::vector<std::uint32_t> live_;  ///< sinks per node
};

}  // namespace sph::gravity
