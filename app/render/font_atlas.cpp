#include "font_atlas.h"

#include <imgui.h>

namespace sph::render {

namespace {
constexpr int kFirst = 32, kLast = 126;  // printable ASCII
}

bool FontAtlas::build(std::string* err) {
  // ImFontAtlas needs no ImGui context: it only rasterises and packs glyphs.
  ImFontAtlas atlas;
  atlas.Flags |= ImFontAtlasFlags_NoMouseCursors | ImFontAtlasFlags_NoBakedLines;
  ImFont* font = atlas.AddFontDefault();  // ProggyClean, 13 px
  unsigned char* pixels = nullptr;
  int w = 0, h = 0, bpp = 0;
  atlas.GetTexDataAsAlpha8(&pixels, &w, &h, &bpp);
  if (font == nullptr || pixels == nullptr || w <= 0 || h <= 0 || bpp != 1) {
    if (err) *err = "could not rasterise the overlay font";
    return false;
  }
  width_ = w;
  height_ = h;
  coverage_.assign(pixels, pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  line_height_ = font->FontSize;
  for (int c = kFirst; c <= kLast; ++c) {
    const ImFontGlyph* g = font->FindGlyph(static_cast<ImWchar>(c));
    if (g == nullptr) continue;
    glyphs_[static_cast<std::size_t>(c - kFirst)] = {g->X0, g->Y0, g->X1, g->Y1, g->U0,
                                                     g->V0, g->U1, g->V1, g->AdvanceX};
  }
  return true;
}

const Glyph& FontAtlas::glyph(char c) const {
  const int i = (c >= kFirst && c <= kLast) ? c : '?';
  return glyphs_[static_cast<std::size_t>(i - kFirst)];
}

float FontAtlas::measure(std::string_view text) const {
  float w = 0.f;
  for (char c : text) w += glyph(c).advance;
  return w;
}

}  // namespace sph::render
