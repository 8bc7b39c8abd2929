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

/// The range a field is shown with. Auto: the settings' percentiles of the finite values of the fluid
/// (leaving out particles whose `kind` is non-zero, i.e. walls; empty kind = all fluid), at 0 and 100
/// the field's min/max (recomputed if the snapshot's are not finite); fixed: the settings' range. A
/// degenerate range [v, v] is widened symmetrically so that v maps to the middle of the colour map.
ValueRange resolve_range(const sph::SnapshotField& field, const ViewSettings& view,
                         std::span<const std::uint8_t> kind = {});
/// The fluid's finite values between percentiles lo and hi (in [0, 100]; nearest rank), not widened;
/// {0, 0} without a finite value.
ValueRange percentile_range(std::span<const float> values, float lo, float hi, std::span<const std::uint8_t> kind = {});
/// Whether the fluid's values between the 1st and 99th percentiles are all positive and span more than
/// two decades (hi > 100 lo): a linear colour map then shows one colour on most particles (Evrard's
/// density, 0.07 to 10.5), so the plane and 3D views colour by log10 (ViewSettings::auto_log).
bool spans_decades(std::span<const float> values, std::span<const std::uint8_t> kind = {});
/// Same widening for any [lo, hi] (also used for plot limits).
ValueRange widen_degenerate(float lo, float hi);

/// "field 'foo' is not in this snapshot; available: rho, p, u" (or "...; it has no fields").
std::string missing_field_message(const sph::Snapshot& snap, std::string_view name);

}  // namespace sph::render
