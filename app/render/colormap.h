// Perceptually uniform colour maps (viridis default, magma, cividis) and the diverging coolwarm map:
// value -> colour on the CPU, and the 256-entry RGBA8 table the GPU samples with linear filtering.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sph::render {

/// sRGB colour, channels in [0,1].
struct Rgb {
  float r = 0.f, g = 0.f, b = 0.f;
};

enum class Colormap { Viridis, Magma, Cividis, Coolwarm };

inline constexpr int kColormapLutSize = 256;  ///< entries of the GPU table
using ColormapLut = std::array<std::uint8_t, kColormapLutSize * 4>;  ///< RGBA8, entry i at t = i/255

/// Names accepted by parse_colormap, in menu order ("viridis" first: the default).
std::span<const std::string_view> colormap_names();
/// "viridis, magma, cividis, coolwarm" (for error messages).
std::string colormap_name_list();
std::optional<Colormap> parse_colormap(std::string_view name);
std::string_view to_string(Colormap map);

/// The map evaluated from its published control points (piecewise linear), t clamped to [0,1].
Rgb colormap_exact(Colormap map, float t);
/// The 256-entry RGBA8 table sent to the GPU: entry i is colormap_exact at t0 + (i/255)(1 - t0), t0 =
/// colormap_low_end, rounded to 8 bits; alpha 255.
const ColormapLut& colormap_lut(Colormap map);
/// What the GPU shows for t: the 8-bit table linearly interpolated, as GL_LINEAR sampling does
/// at texture coordinate (t*255 + 0.5)/256. Tests compare rendered pixels with this.
Rgb colormap_rgb(Colormap map, float t);
/// WCAG 2 contrast ratio (L1 + 0.05) / (L2 + 0.05) of two sRGB colours, L the relative luminance.
float contrast_ratio(Rgb a, Rgb b);
/// Least contrast ratio of every shown colour against the backgrounds particles are drawn on (the
/// plot fill and the frame): dark purple or black dots on dark grey were hard to see.
inline constexpr float kMinBackgroundContrast = 1.5f;
/// Where the shown map starts on the published one: the smallest t0 from which every colour keeps
/// kMinBackgroundContrast. The table (and so colormap_rgb) shows published t0 + t (1 - t0).
float colormap_low_end(Colormap map);

/// A colour that stands out against every colour of the map (exact-solution curves).
Rgb colormap_contrast(Colormap map);

}  // namespace sph::render
