// Barnes-Hut tree of self-gravity (seed 003 App. A; Barnes & Hut 1986): an octree in 3D (quadtree in
// 2D, binary tree in 1D) of cubic cells split until a cell holds at most `leaf_size` particles; each
// cell keeps its mass, centre of mass, second moments (quadrupole) and bmax, the largest distance from
// its centre of mass to any of its particles.
//
// Opening criterion, two parts:
// - geometric (Barnes 1994's "modified" form): a cell of side l is used whole, as monopole plus
//   quadrupole, for a particle at distance r from its centre of mass only when r > l/theta + delta,
//   delta being the offset of the centre of mass from the cell's geometric centre. The classic
//   l/r < theta test fails for a particle just outside a cell whose mass sits at the near edge; the delta
//   term opens such cells. A cell is never used whole by a particle within bmax of its centre of mass.
// - relative guard (in the spirit of Springel 2005's relative criterion, for the quadrupole order): and
//   only when the first term the expansion drops, M bmax^3 / r^5, is at most tol |a_i|, |a_i| taken
//   from a first, coarse walk at theta = 1 (no history, so the result depends on the positions only).
//   Near the centre of a sphere |a| -> 0 and any fixed theta gives large relative errors there: with the
//   side alone, theta = 0.5 gave 0.1% RMS but 4.3% largest error on a Plummer sphere of 4000 (at a
//   particle with |a| = 0.017 against ~0.3 typical); the guard (tol = 1e-3) gives 0.05% and 0.46%. A
//   diagonal-size criterion reached 0.27% largest error but with 2.8x the interactions at N = 1e5, and
//   its cost grew faster than N log N up to 1e5. The guard makes large theta cost about what
//   theta = 0.7 does: it is what keeps the error bounded; tol = 0 shows plain Barnes-Hut.
// theta = 0 opens every cell: direct summation in another order. With kernel softening a cell is used
// whole only if, in addition, every pair is beyond both supports (r > bmax + S max(h_i, h_cell)), where
// the law is exactly Newtonian. Plummer softening enters the multipoles as r^2 -> r^2 + eps^2.
//
// The build is serial and deterministic; the walk is a gather per particle, so accelerations are bitwise
// the same for any thread count.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "gravity/softening.h"
#include "gravity/sources.h"

namespace sph::gravity {

struct TreeNode {
  double center[3];   ///< geometric centre of the cubic cell [length]
  double half;        ///< half its side [length]
  double com[3];      ///< centre of mass [length]
  double mass;        ///< total mass [mass]
  double S[6];        ///< second moments sum m d d^T about the com: xx, xy, xz, yy, yz, zz [mass length^2]
  double bmax;        ///< largest |x - com| of its particles [length]
  double delta;       ///< |com - center|, the offset of the centre of mass [length]
  double hmax;        ///< largest h of its particles [length]
  std::uint32_t first, count;  ///< its particles: order()[first .. first + count)
  std::uint32_t child;         ///< index of the first child (children are contiguous); 0 for a leaf
  std::uint8_t n_child;        ///< number of (non-empty) children; 0 for a leaf
  std::uint8_t depth;
};

/// Adds the field (per unit G) of a cell's monopole and quadrupole at offset (dx, dy, dz) from its
/// centre of mass, softened by e2 = eps^2, to a and phi.
void multipole_field(const TreeNode& nd, double dx, double dy, double dz, double e2, double& ax, double& ay,
                     double& az, double& phi);

/// A cell of one particle's walk: used whole (monopole + quadrupole) or a leaf summed pair by pair.
struct CellUse {
  std::uint32_t node;  ///< index into BarnesHutTree::nodes()
  bool whole;
};

class BarnesHutTree {
 public:
  static constexpr double kEstimateTheta = 1.0;  ///< opening angle of the estimate pass
  static constexpr double kDefaultTol = 1e-3;    ///< the relative guard's default tolerance
  /// Builds the tree of particles 0..s.n-1.
  void build(const Sources& s, std::uint32_t leaf_size = 8);
  const std::vector<TreeNode>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& order() const { return order_; }
  /// Positions, masses and h in tree order (slot t holds particle order()[t]).
  const std::array<std::vector<double>, 3>& sorted_x() const { return sx_; }
  const std::vector<double>& sorted_m() const { return sm_; }
  const std::vector<double>& sorted_h() const { return sh_; }
  /// Accelerations and potentials of every particle (of the sinks s.active names, the others keeping
  /// out's values; Result::begin) from the tree at opening angle theta, with the relative guard at
  /// tolerance tol (0: none; then one walk).
  void evaluate(const Sources& s, const PairLaw& law, double G, double theta, Result& out,
                double tol = kDefaultTol) const;
  /// The cells the walk of particle i (storage index) takes at theta and tol, in walk order: what the
  /// tree opens for it (the GUI's overlay; its sum is that particle's acceleration from evaluate()).
  std::vector<CellUse> interactions(const Sources& s, const PairLaw& law, double theta, double tol,
                                    std::size_t i) const;

 private:
  /// The relative guard of the main pass: a cell is used whole only if M bmax^3 / d^5 <= tol |a_i|.
  struct Guard {
    const std::vector<double>* a_est = nullptr;  ///< |a_i| per unit G, in tree order; none: no guard
    double tol = 0.0;
  };
  struct Opening {
    double theta = 0.0, inv_theta = 0.0, support = 0.0;
    bool kernel = false;
  };
  Opening opening(const PairLaw& law, double theta) const;
  /// The walk of target t (tree order): on_cell(node, nd, dx, dy, dz) for each cell used whole,
  /// on_leaf(node, nd) for each leaf summed pair by pair; allowed = tol |a_t| (1e300: no guard).
  template <class OnCell, class OnLeaf>
  void visit(std::size_t t, const Opening& op, double allowed, std::vector<std::uint32_t>& stack, OnCell&& on_cell,
             OnLeaf&& on_leaf) const;
  /// One walk for every target (each sink flagged in `active`, storage order, when not null), results per
  /// unit G in tree order (added to out's term counts).
  void walk(const Sources& s, const PairLaw& law, double theta, const Guard& guard, Result& out,
            const std::uint8_t* active = nullptr) const;
  void split(const Sources& s, std::uint32_t node, std::uint32_t leaf_size);
  void moments(const Sources& s, std::uint32_t node);
  std::vector<TreeNode> nodes_;
  std::vector<std::uint32_t> order_, scratch_;
  std::array<std::vector<double>, 3> sx_;  ///< positions in tree order
  std::vector<double> sm_, sh_;            ///< masses and h in tree order
  mutable Result walked_;                  ///< a walk's results in tree order
  mutable std::vector<double> a_est_;      ///< |a| of the estimate pass, tree order
};

}  // namespace sph::gravity
