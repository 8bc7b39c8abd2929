// Report::tree_cells, the tree overlay: the cells of one particle's Barnes-Hut walk, as self-gravity's
// tree stage would take them now (same build, opening angle, guard and softening), for a viewer to draw.
#include <optional>

#include "gravity/barnes_hut.h"
#include "sph/neighbour_cache.h"
#include "sph/report.h"

namespace sph {

std::vector<TreeCell> Report::tree_cells(std::size_t k) const {
  std::vector<TreeCell> cells;
  const Params& prm = in_.cfg.params;
  if (prm.physics.gravity != GravityType::Tree || k >= in_.by_id.size()) return cells;
  const std::size_t i = in_.by_id[k];
  const gravity::Sources s = gravity::Sources::of(in_.p);
  if (i >= s.n) return cells;  // a wall particle: not in the tree
  gravity::PairLaw law;
  law.kind = prm.gravity.softening;
  law.eps2 = prm.gravity.eps * prm.gravity.eps;
  std::optional<gravity::KernelSoftening> kernel;
  if (kernel_softened(law.kind)) law.kernel = &kernel.emplace(prm.kernel.type);
  gravity::BarnesHutTree tree;
  tree.build(s);
  for (const gravity::CellUse& u : tree.interactions(s, law, prm.gravity.theta, prm.gravity.tol, i)) {
    const gravity::TreeNode& nd = tree.nodes()[u.node];
    TreeCell c;
    for (int a = 0; a < 3; ++a) c.center[a] = static_cast<float>(nd.center[a]);
    c.half = static_cast<float>(nd.half);
    c.whole = u.whole;
    cells.push_back(c);
  }
  return cells;
}

}  // namespace sph
