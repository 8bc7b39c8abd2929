#include "colormap.h"

#include <algorithm>
#include <cmath>

#include "colormap_tables.h"
#include "palette.h"

namespace sph::render {

namespace {

constexpr std::string_view kNames[] = {"viridis", "magma", "cividis", "coolwarm"};
constexpr Colormap kMaps[] = {Colormap::Viridis, Colormap::Magma, Colormap::Cividis, Colormap::Coolwarm};

float clamp01(float t) { return std::isnan(t) ? 0.f : std::clamp(t, 0.f, 1.f); }

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float relative_luminance(Rgb c) {
  return 0.2126f * srgb_to_linear(c.r) + 0.7152f * srgb_to_linear(c.g) + 0.0722f * srgb_to_linear(c.b);
}

bool stands_out(Rgb c) {
  for (const Rgba& bg : {palette::kPlotFill, palette::kBackground})
    if (contrast_ratio(c, {bg.r, bg.g, bg.b}) < kMinBackgroundContrast + 0.02f) return false;  // margin: 8-bit table
  return true;
}

// Scans down from the top in steps of 1/1024 of the published map; stops below the first colour that fails.
float find_low_end(Colormap map) {
  constexpr int kSteps = 1024;
  int k = kSteps;
  while (k > 0 && stands_out(colormap_exact(map, static_cast<float>(k - 1) / kSteps))) --k;
  return static_cast<float>(k) / kSteps;
}

ColormapLut build_lut(Colormap map) {
  ColormapLut lut{};
  const float t0 = colormap_low_end(map);
  for (int i = 0; i < kColormapLutSize; ++i) {
    const Rgb c = colormap_exact(map, t0 + (1.f - t0) * static_cast<float>(i) / (kColormapLutSize - 1));
    const float ch[3] = {c.r, c.g, c.b};
    for (int k = 0; k < 3; ++k)
      lut[4 * i + k] = static_cast<std::uint8_t>(std::lround(std::clamp(ch[k], 0.f, 1.f) * 255.f));
    lut[4 * i + 3] = 255;
  }
  return lut;
}

}  // namespace

std::span<const std::string_view> colormap_names() { return kNames; }

std::string colormap_name_list() {
  std::string s;
  for (auto n : kNames) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

std::optional<Colormap> parse_colormap(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kNames); ++i)
    if (kNames[i] == name) return kMaps[i];
  return std::nullopt;
}

std::string_view to_string(Colormap map) { return colormap_table(map).name; }

Rgb colormap_exact(Colormap map, float t) {
  const ColormapTable& table = colormap_table(map);
  const float pos = clamp01(t) * table.position_scale;
  const auto& pts = table.points;
  // First control point at or beyond pos; interpolate with its predecessor.
  std::size_t j = 1;
  while (j + 1 < pts.size() && pts[j].position < pos) ++j;
  const ControlPoint& a = pts[j - 1];
  const ControlPoint& b = pts[j];
  const float w = std::clamp((pos - a.position) / (b.position - a.position), 0.f, 1.f);
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)};
}

float contrast_ratio(Rgb a, Rgb b) {
  const float la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05f) / (std::min(la, lb) + 0.05f);
}

float colormap_low_end(Colormap map) {
  static const float kLow[] = {find_low_end(Colormap::Viridis), find_low_end(Colormap::Magma),
                               find_low_end(Colormap::Cividis), find_low_end(Colormap::Coolwarm)};
  return kLow[static_cast<int>(map)];
}

const ColormapLut& colormap_lut(Colormap map) {
  // Built once per map on first use; const afterwards (safe to share between threads).
  static const ColormapLut kLuts[] = {build_lut(Colormap::Viridis), build_lut(Colormap::Magma),
                                      build_lut(Colormap::Cividis), build_lut(Colormap::Coolwarm)};
  return kLuts[static_cast<int>(map)];
}

Rgb colormap_rgb(Colormap map, float t) {
  const ColormapLut& lut = colormap_lut(map);
  const float pos = clamp01(t) * (kColormapLutSize - 1);
  const int i = std::min(static_cast<int>(pos), kColormapLutSize - 2);
  const float w = pos - static_cast<float>(i);
  auto ch = [&](int k) {
    return (lut[4 * i + k] + w * (lut[4 * (i + 1) + k] - lut[4 * i + k])) / 255.f;
  };
  return {ch(0), ch(1), ch(2)};
}

Rgb colormap_contrast(Colormap map) { return colormap_table(map).contrast; }

}  // namespace sph::render
