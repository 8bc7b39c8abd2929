// Residual panels of profiles: a strip under a panel that shows what the panel's curves hide. A comparison
// of two 1D runs shows B - A (B interpolated at A's particles), a 1D sweep without an exact curve each run
// minus A: runs that overlap on the profile, such as M4 against M6 on Sod, separate there. Otherwise each run minus the exact curve at its particles, on a
// zero line: where a run makes its error.
#pragma once
#include <cstddef>
#include <vector>

#include "profile_panel.h"

namespace sph::render {

/// v(c) by linear interpolation on the curve's abscissae (non-decreasing); NaN outside them.
float exact_at(const sph::ExactCurve& curve, float c);

/// Whether p has a residual panel: 1D runs against the first (ProfilePanel::versus_first), or an exact curve.
bool has_residuals(const ProfilePanel& p);

/// The residual panel of `p` (see above): y limits symmetric about zero, the zero line as its curve.
ProfilePanel residual_panel(const ProfilePanel& p, int axis);

/// Draws p, and under it its residual panel when `residuals` and has_residuals(p) (p's area split 70/30,
/// the two y label columns as wide). Returns f.batches.size() once p is drawn (before its residual
/// panel), for the caller that takes p's box as the frame's plot.
std::size_t compose_with_residuals(FrameBuild& f, ProfilePanel p, const ViewSettings& view, const ShownField& shown,
                                   int axis, bool primary, bool residuals);

}  // namespace sph::render
