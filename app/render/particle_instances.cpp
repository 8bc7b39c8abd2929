#include "particle_instances.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/snapshot.h"

namespace sph::render {

void build_instances(const sph::Snapshot& snap, const ShownField& shown, Placement placement, float radius_scale,
                     std::vector<float>* out) {
  const std::size_t n = std::min(snap.count, snap.x.size());
  const std::vector<float>* values = shown.field ? &shown.field->values : nullptr;
  auto at = [](const std::vector<float>& v, std::size_t i, float fallback) { return i < v.size() ? v[i] : fallback; };
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  out->resize(out->size() + n * kInstanceFloats);
  float* p = out->data() + out->size() - n * kInstanceFloats;
  for (std::size_t i = 0; i < n; ++i, p += kInstanceFloats) {
    const float value = values ? at(*values, i, kNaN) : kNaN;
    p[0] = snap.x[i];
    if (placement == Placement::Profile) {
      p[1] = std::isfinite(value) ? value : 0.f;
      p[2] = 0.f;
    } else {
      p[1] = snap.dim >= 2 ? at(snap.y, i, 0.f) : 0.f;
      p[2] = snap.dim >= 3 ? at(snap.z, i, 0.f) : 0.f;
    }
    p[3] = radius_scale * at(snap.h, i, 0.f);
    p[4] = value;
  }
}

bool has_smoothing_lengths(const sph::Snapshot& snap) {
  for (float h : snap.h)
    if (h > 0.f && std::isfinite(h)) return true;
  return false;
}

}  // namespace sph::render
