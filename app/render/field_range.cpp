#include "field_range.h"

#include <algorithm>
#include <cmath>

#include "sph/snapshot.h"

namespace sph::render {

ValueRange widen_degenerate(float lo, float hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.f, 1.f};
  if (lo > hi) std::swap(lo, hi);
  const float scale = std::max({std::abs(lo), std::abs(hi), 1e-30f});
  if (hi - lo > 1e-6f * scale) return {lo, hi};
  const float mid = 0.5f * (lo + hi);
  const float d = std::max(std::abs(mid) * 1e-3f, 1e-6f);  // +-0.1% (or 1e-6 around zero)
  return {mid - d, mid + d};
}

ValueRange resolve_range(const sph::SnapshotField& field, const ViewSettings& view, std::span<const std::uint8_t> kind) {
  if (!view.auto_range) return widen_degenerate(view.range_min, view.range_max);
  float lo = field.min, hi = field.max;
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi || (lo == 0.f && hi == 0.f)) {
    lo = INFINITY;
    hi = -INFINITY;
    for (std::size_t i = 0; i < field.values.size(); ++i) {
      const float v = field.values[i];
      if (std::isfinite(v) && !(i < kind.size() && kind[i] != 0)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (lo > hi) lo = hi = 0.f;  // no finite value at all
  }
  return widen_degenerate(lo, hi);
}

std::string missing_field_message(const sph::Snapshot& snap, std::string_view name) {
  std::string msg = "field '" + std::string(name) + "' is not in this snapshot";
  if (snap.fields.empty()) return msg + "; it has no fields";
  msg += "; available:";
  for (std::size_t i = 0; i < snap.fields.size(); ++i) msg += (i ? ", " : " ") + snap.fields[i].name;
  return msg;
}

}  // namespace sph::render
