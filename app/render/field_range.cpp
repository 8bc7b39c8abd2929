#include "field_range.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

ValueRange percentile_range(std::span<const float> values, float lo, float hi, std::span<const std::uint8_t> kind) {
  std::vector<float> v;
  v.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::isfinite(values[i]) && !(i < kind.size() && kind[i] != 0)) v.push_back(values[i]);
  if (v.empty()) return {0.f, 0.f};
  const auto rank = [&](float pct) {  // nearest rank: index round(p/100 (n-1))
    const double q = std::clamp(static_cast<double>(pct), 0.0, 100.0) / 100.0;
    return static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  };
  const std::size_t a = rank(std::min(lo, hi)), b = rank(std::max(lo, hi));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(a), v.end());
  const float va = v[a];
  std::nth_element(v.begin() + static_cast<std::ptrdiff_t>(a), v.begin() + static_cast<std::ptrdiff_t>(b), v.end());
  return {va, v[b]};
}

ValueRange resolve_range(const sph::SnapshotField& field, const ViewSettings& view, std::span<const std::uint8_t> kind) {
  if (!view.auto_range) return widen_degenerate(view.range_min, view.range_max);
  if (view.percentile_lo > 0.f || view.percentile_hi < 100.f) {
    const ValueRange r = percentile_range(field.values, view.percentile_lo, view.percentile_hi, kind);
    return widen_degenerate(r.min, r.max);
  }
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

bool spans_decades(std::span<const float> values, std::span<const std::uint8_t> kind) {
  const ValueRange r = percentile_range(values, 1.f, 99.f, kind);
  return r.min > 0.f && r.max > 100.f * r.min;
}

}  // namespace sph::render
