// The particles' storage order: a spatial (Morton) sort every few steps, and a new set of particles
// taken over from a stage (resampling); by_id() follows both.
#include <algorithm>

#include "core/pipeline.h"
#include "core/spatial_order.h"
#include "core/stage.h"
#include "integrators/block_steps.h"
#include "sph/world.h"

namespace sph {

void World::adopt(Particles&& fresh) {
  p_ = std::move(fresh);
  p_.add_fields(pipeline_->fields());
  apply_boundaries(domain_, p_);
  integrator_->reset();  // its history was per particle
  if (block_) block_->synchronise();
  lists_.clear();
  rates_known_ = false;
  t_last_eval_ = -1.0;
  by_id_.clear();
  reorder();
}

void World::reorder() {
  // Morton order over cells of the kernel's support at the largest h: a cell's neighbours are mostly
  // in the cells next to it on the curve. Walls never move: sorted once, then the order is kept.
  const std::size_t nf = p_.fluid(), n = p_.size();
  const auto& h = p_[Field::H];
  double hmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, h[i]);
  double cell = kernel_.support() * hmax;
  if (cell <= 0.0) {  // point masses (h = 0): cells of 1/1024 of the extent
    double extent = 0.0;
    for (int k = 0; k < p_.dim(); ++k) {
      const auto [lo, hi] = std::minmax_element(p_.x[k].begin(), p_.x[k].begin() + static_cast<std::ptrdiff_t>(nf));
      if (nf > 0) extent = std::max(extent, *hi - *lo);
    }
    cell = extent / 1024.0;
  }
  std::vector<std::uint32_t> order = morton_order(p_, 0, nf, cell);
  if (by_id_.empty()) {
    const std::vector<std::uint32_t> walls = morton_order(p_, nf, n, cell);
    order.insert(order.end(), walls.begin(), walls.end());
  } else {
    for (std::size_t i = nf; i < n; ++i) order.push_back(static_cast<std::uint32_t>(i));
  }
  p_.permute(order);
  integrator_->permute(order);
  if (block_) block_->permute(order);
  lists_.permute(order);  // the lists stay valid for the current state
  for (const auto& s : pipeline_->stages()) s->permute(order);
  by_id_.resize(n);
  for (std::size_t i = 0; i < n; ++i) by_id_[i] = static_cast<std::uint32_t>(i);
  std::sort(by_id_.begin(), by_id_.end(), [&](std::uint32_t a, std::uint32_t b) { return p_.id[a] < p_.id[b]; });
}

}  // namespace sph
