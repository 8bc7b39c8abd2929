// SceneSpec helpers: default scene values and the slot options a scene accepts.
#include <algorithm>

#include "sph/scene.h"

namespace sph {

SceneValues SceneSpec::default_values() const {
  SceneValues v;
  for (const auto& p : params) v[p.name] = p.value;
  return v;
}

bool SceneSpec::allows(Slot s, const std::string& option) const {
  const auto& list = allowed[static_cast<std::size_t>(s)];
  // self-gravity needs an open domain (no periodic images: that would need Ewald sums): a scene offers
  // it only by listing its options
  if (s == Slot::Gravity && list.empty()) return option == "none";
  // the finite pointset method has scenes of its own (seed 002): likewise offered only by listing it
  if (s == Slot::Fpm && list.empty()) return option == "none";
  return list.empty() || std::find(list.begin(), list.end(), option) != list.end();
}

int find_column(const std::vector<RefColumn>& columns, const std::string& name) {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace sph
