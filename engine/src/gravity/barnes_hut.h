// Barnes-Hut tree of self-gravity (seed 003 App. A; Barnes & Hut 1986): an octree in 3D (quadtree in
// 2D, binary tree in 1D) of cubic cells split until a cell holds at most `leaf_size` particles; each
// cell keeps its mass, centre of mass, second moments (quadrupole) and bmax, the largest distance from
// its centre of mass to any of its particles.
//
// Opening criterion (Barnes 1994's "modified" form, with the cell's diagonal as its size): a cell of
// diagonal l (2 sqrt(d) times its half side in d dimensions) is used whole, as monopole plus quadrupole,
// for a particle at distance r from its centre of mass when r > l/theta + delta, delta being the offset
// of the centre of mass from the cell's geometric centre. The classic s/r < theta test fails for a
// particle just outside a cell whose mass sits at the near edge; the delta term opens such cells. A cell
// is never used whole by a particle within bmax of its centre of mass (inside it). With the side instead
// of the diagonal, theta = 0.5 gave 0.1% RMS but 4.3% largest force error on a Plummer sphere (at the
// centre, where |a| is small); with the diagonal, 0.009% and 0.27% (the issue asks 0.1% and 1%), at
// twice the interactions. theta = 0 opens every cell: direct summation in another order. With kernel
// softening a cell is used whole only if, in addition, every pair is beyond both supports
// (r > bmax + S max(h_i, h_cell)), where the law is exactly Newtonian. Plummer softening enters the
// multipoles as r^2 -> r^2 + eps^2.
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

class BarnesHutTree {
 public:
  /// Builds the tree of particles 0..s.n-1.
  void build(const Sources& s, std::uint32_t leaf_size = 8);
  const std::vector<TreeNode>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& order() const { return order_; }
  /// Accelerations and potentials of every particle from the tree at opening angle theta.
  void evaluate(const Sources& s, const PairLaw& law, double G, double theta, Result& out) const;

 private:
  void split(const Sources& s, std::uint32_t node, std::uint32_t leaf_size);
  void moments(const Sources& s, std::uint32_t node);
  std::vector<TreeNode> nodes_;
  std::vector<std::uint32_t> order_, scratch_;
  std::array<std::vector<double>, 3> sx_;  ///< positions in tree order
  std::vector<double> sm_, sh_;            ///< masses and h in tree order
};

}  // namespace sph::gravity
