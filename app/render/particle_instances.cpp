#include "particle_instances.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "profile_axis.h"
#include "sph/snapshot.h"

namespace sph::render {

void build_instances(const sph::Snapshot& snap, const ShownField& shown, const InstanceOptions& o,
                     std::vector<float>* out, std::vector<std::uint32_t>* index) {
  const std::size_t n = std::min(snap.count, snap.x.size());
  const std::vector<float>* values = shown.field ? &shown.field->values : nullptr;
  auto at = [](const std::vector<float>& v, std::size_t i, float fallback) { return i < v.size() ? v[i] : fallback; };
  const std::vector<float>* coords[3] = {&snap.x, &snap.y, &snap.z};
  const bool profile = o.placement == Placement::Profile;
  const bool keep_walls = o.walls && !profile;
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const std::size_t first = out->size();
  out->resize(first + n * kInstanceFloats);  // the most we write; trimmed below when walls are left out
  float* p = out->data() + first;
  for (std::size_t i = 0; i < n; ++i) {
    const bool wall = snap.is_wall(i);
    if (wall && !keep_walls) continue;
    if (!profile && o.cut_axis >= 0 && at(*coords[std::min(o.cut_axis, 2)], i, 0.f) > o.cut_at) continue;  // cut away
    const float value = values ? at(*values, i, kNaN) : kNaN;
    if (profile) {
      p[0] = profile_coordinate(snap, i, o.axis);
      const float y = o.y ? at(*o.y, i, kNaN) : value;
      p[1] = std::isfinite(y) ? y : 0.f;
      p[2] = 0.f;
    } else {
      p[0] = snap.x[i];
      p[1] = snap.dim >= 2 ? at(snap.y, i, 0.f) : 0.f;
      p[2] = snap.dim >= 3 ? at(snap.z, i, 0.f) : 0.f;
    }
    p[3] = o.radius_scale * at(snap.h, i, 0.f);
    p[4] = value;
    p[5] = wall || o.solid ? 1.f : 0.f;
    p += kInstanceFloats;
    if (index) index->push_back(static_cast<std::uint32_t>(i));
  }
  out->resize(static_cast<std::size_t>(p - out->data()));
}

bool has_smoothing_lengths(const sph::Snapshot& snap) {
  for (float h : snap.h)
    if (h > 0.f && std::isfinite(h)) return true;
  return false;
}

}  // namespace sph::render
