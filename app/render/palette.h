// Colours of everything that is not data (and of wall particles): a dark-grey theme readable on a
// projector, and a white-on-black one for high contrast (Chrome).
#pragma once
#include "overlay_types.h"

namespace sph::render::palette {

inline constexpr Rgba kBackground{0.110f, 0.110f, 0.120f, 1.f};  ///< frame (sRGB ~ 28,28,31)
inline constexpr Rgba kPlotFill{0.165f, 0.165f, 0.180f, 1.f};    ///< inside axes boxes
inline constexpr Rgba kAxis{0.62f, 0.62f, 0.66f, 1.f};           ///< axes frame and ticks
inline constexpr Rgba kGrid{0.26f, 0.26f, 0.28f, 1.f};           ///< grid lines (1D)
inline constexpr Rgba kDomain{0.45f, 0.45f, 0.50f, 1.f};         ///< domain box outline (2D, 3D)
inline constexpr Rgba kText{0.92f, 0.92f, 0.94f, 1.f};           ///< labels
inline constexpr Rgba kDimText{0.62f, 0.62f, 0.66f, 1.f};        ///< secondary labels
inline constexpr Rgba kWarning{1.00f, 0.70f, 0.25f, 1.f};        ///< "field not found" and similar
inline constexpr Rgba kLegendFill{0.08f, 0.08f, 0.09f, 0.80f};   ///< legend box
inline constexpr Rgba kInvalid{1.00f, 0.00f, 1.00f, 1.f};        ///< particles whose value is NaN/inf
inline constexpr Rgba kNoField{0.80f, 0.80f, 0.82f, 1.f};        ///< particles when no field is shown
/// Wall particles, whatever the field: a neutral grey at least 43/255 (per channel) from every colour
/// of the four maps (cividis passes nearest, through its grey middle), and from kNoField.
inline constexpr Rgba kWall{0.64f, 0.64f, 0.64f, 1.f};
/// Reference outlines (2D), one colour per distinct label in order: near white first (most scenes
/// have one label), then amber, sky blue, pink; each drawn on kOutlineHalo, which keeps it visible
/// over any colour of any map.
inline constexpr Rgba kOutlines[8] = {
    {0.98f, 0.98f, 0.98f, 1.f}, {1.00f, 0.78f, 0.25f, 1.f}, {0.45f, 0.80f, 1.00f, 1.f}, {1.00f, 0.50f, 0.80f, 1.f},
    {0.55f, 0.90f, 0.45f, 1.f}, {1.00f, 0.45f, 0.35f, 1.f}, {0.75f, 0.60f, 1.00f, 1.f}, {0.30f, 0.85f, 0.80f, 1.f}};
inline constexpr Rgba kOutlineHalo{0.04f, 0.04f, 0.05f, 1.f};  ///< dark rim under the outlines
inline constexpr Rgba kKernelSupport{0.55f, 0.85f, 1.00f, 1.f};  ///< the inspected particle's kernel support

/// The colours of the frame around the data, chosen per frame (ViewSettings::high_contrast): the dark-grey
/// theme above, or white on black for a washed-out projector (every label white, a brighter grid, an
/// opaque legend box).
struct Chrome {
  Rgba background, plot_fill, axis, grid, domain, text, dim_text, legend_fill;
};
inline constexpr Chrome kStandard{kBackground, kPlotFill, kAxis, kGrid, kDomain, kText, kDimText, kLegendFill};
inline constexpr Chrome kHighContrast{{0.f, 0.f, 0.f, 1.f},       {0.035f, 0.035f, 0.04f, 1.f}, {1.f, 1.f, 1.f, 1.f},
                                      {0.42f, 0.42f, 0.44f, 1.f}, {0.85f, 0.85f, 0.88f, 1.f},   {1.f, 1.f, 1.f, 1.f},
                                      {0.95f, 0.95f, 0.95f, 1.f}, {0.f, 0.f, 0.f, 0.94f}};
inline const Chrome& chrome(bool high_contrast) { return high_contrast ? kHighContrast : kStandard; }

}  // namespace sph::render::palette
