// Which field is shown and over which value range: the auto/fixed choice, and the guards that keep
// the colour mapping finite for constant fields or fields with non-finite values.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "view_settings.h"

namespace sph {
struct Snapshot;
struct SnapshotField;
}  // namespace sph

namespace sph::render {

struct ValueRange {
  float min = 0.f, max = 1.f;  ///< min < max always [field units]
};

/// The range a field is shown with. Auto: the field's min/max over finite values of the fluid
/// (recomputed if the snapshot's are not finite, leaving out particles whose `kind` is non-zero, i.e.
/// walls; empty kind = all fluid); fixed: the settings' range. A degenerate range [v, v] is widened
/// symmetrically so that v maps to the middle of the colour map.
ValueRange resolve_range(const sph::SnapshotField& field, const ViewSettings& view,
                         std::span<const std::uint8_t> kind = {});
/// Same widening for any [lo, hi] (also used for plot limits).
ValueRange widen_degenerate(float lo, float hi);

/// "field 'foo' is not in this snapshot; available: rho, p, u" (or "...; it has no fields").
std::string missing_field_message(const sph::Snapshot& snap, std::string_view name);

}  // namespace sph::render
