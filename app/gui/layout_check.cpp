// Text layout checks on Dear ImGui's draw data (layout_check.h).
#include "layout_check.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace sph::gui {
namespace {

struct Glyph {
  float x0, y0, x1, y1;
  unsigned c;
  int list;
  bool cut;  ///< drawn partly (cut by the clip rectangle, or clipped on the CPU)
};

/// Atlas glyphs by their top-left texture coordinate, with their bottom-right one.
using GlyphTable = std::map<std::pair<float, float>, std::pair<unsigned, ImVec2>>;

GlyphTable glyph_table(const ImFontAtlas& atlas) {
  GlyphTable t;
  for (const ImFont* font : atlas.Fonts)
    for (const ImFontGlyph& g : font->Glyphs)
      if (g.Visible) t[{g.U0, g.V0}] = {g.Codepoint, ImVec2(g.U1, g.V1)};
  return t;
}

bool starts_with(const char* s, const char* prefix) { return s && std::string(s).rfind(prefix, 0) == 0; }

/// Whether the draw list's window, or a window it lies in, shows a vertical scroll bar.
bool scrolls(const char* owner) {
  for (const ImGuiWindow* w = ImGui::FindWindowByName(owner); w != nullptr; w = w->ParentWindow)
    if (w->ScrollbarY) return true;
  return false;
}

/// The glyphs of one draw list, in drawing order.
void list_glyphs(const ImDrawList& l, int index, const GlyphTable& table, bool may_scroll, std::vector<Glyph>& out) {
  for (const ImDrawCmd& cmd : l.CmdBuffer) {
    if (cmd.UserCallback) continue;
    // a glyph is a PrimRectUV quad, indices (i, i+1, i+2, i, i+2, i+3) from its top-left corner, among
    // triangles of every other shape: tried at every triangle
    for (unsigned k = 0; k + 6 <= cmd.ElemCount; k += 3) {
      const ImDrawIdx* idx = l.IdxBuffer.Data + cmd.IdxOffset + k;
      if (idx[1] != idx[0] + 1 || idx[2] != idx[0] + 2 || idx[3] != idx[0] || idx[4] != idx[2] || idx[5] != idx[0] + 3)
        continue;
      const ImDrawVert* v = l.VtxBuffer.Data + cmd.VtxOffset;
      const ImDrawVert& a = v[idx[0]];  // top-left
      const ImDrawVert& c = v[idx[2]];  // bottom-right
      const auto it = table.find({a.uv.x, a.uv.y});
      if (it == table.end() || a.pos.x >= c.pos.x || a.pos.y >= c.pos.y) continue;
      k += 3;  // the quad's second triangle
      const ImVec4& clip = cmd.ClipRect;
      // cut on the CPU (RenderTextClipped: the corner's texture coordinate moved) or by the clip rectangle
      const bool x_cut = c.uv.x != it->second.second.x || a.pos.x < clip.x - 0.5f || c.pos.x > clip.z + 0.5f;
      const bool y_cut = !may_scroll && (c.uv.y != it->second.second.y || a.pos.y < clip.y - 0.5f || c.pos.y > clip.w + 0.5f);
      // what shows of it: the part inside the clip rectangle (none: hidden, e.g. scrolled out of view)
      const float x0 = std::max(a.pos.x, clip.x), y0 = std::max(a.pos.y, clip.y);
      const float x1 = std::min(c.pos.x, clip.z), y1 = std::min(c.pos.y, clip.w);
      if (x0 >= x1 || y0 >= y1) {
        if (x_cut && a.pos.y < clip.w && c.pos.y > clip.y)  // cut away whole: no width, its line kept
          out.push_back({a.pos.x, a.pos.y, a.pos.x, c.pos.y, it->second.first, index, true});
        continue;
      }
      out.push_back({x0, y0, x1, y1, it->second.first, index, x_cut || y_cut});
    }
  }
}

/// The glyphs of list `g.list` on g's line (same top edge within half a glyph), left to right, as text.
std::string line_text(const std::vector<Glyph>& all, const Glyph& g) {
  std::vector<const Glyph*> line;
  const float h = g.y1 - g.y0;
  for (const Glyph& o : all)
    if (o.list == g.list && std::abs(o.y0 - g.y0) < 0.5f * h && std::abs(o.x0 - g.x0) < 40.f * h) line.push_back(&o);
  std::sort(line.begin(), line.end(), [](const Glyph* p, const Glyph* q) { return p->x0 < q->x0; });
  std::string s;
  for (const Glyph* o : line) s += o->c < 128 ? static_cast<char>(o->c) : '?';
  return s;
}

/// Whether two glyph boxes, each shrunk by a fifth, overlap (neighbouring letters touch, text over text
/// does not).
bool overlap(const Glyph& a, const Glyph& b) {
  if (a.x1 <= a.x0 || b.x1 <= b.x0) return false;  // a hidden glyph (cut away whole)
  const auto inset = [](float lo, float hi) { return 0.2f * (hi - lo); };
  const float ax = inset(a.x0, a.x1), ay = inset(a.y0, a.y1), bx = inset(b.x0, b.x1), by = inset(b.y0, b.y1);
  return a.x0 + ax < b.x1 - bx && b.x0 + bx < a.x1 - ax && a.y0 + ay < b.y1 - by && b.y0 + by < a.y1 - ay;
}

}  // namespace

bool layout_settled() {
  const ImGuiContext* g = ImGui::GetCurrentContext();
  if (g == nullptr) return true;
  for (const ImGuiWindow* w : g->Windows) {
    if (!w->Active || w->Hidden) continue;
    const ImVec2 drawn(w->DC.CursorMaxPos.x - w->DC.CursorStartPos.x, w->DC.CursorMaxPos.y - w->DC.CursorStartPos.y);
    if (std::abs(drawn.x - w->ContentSize.x) > 1.f || std::abs(drawn.y - w->ContentSize.y) > 1.f) return false;
  }
  return true;
}

LayoutReport check_layout(const ImDrawData& dd, const ImFontAtlas& atlas) {
  const GlyphTable table = glyph_table(atlas);
  std::vector<Glyph> glyphs;
  std::vector<std::string> owners;
  for (int n = 0; n < dd.CmdListsCount; ++n) {
    const ImDrawList& l = *dd.CmdLists[n];
    const char* owner = l._OwnerName ? l._OwnerName : "";
    owners.emplace_back(owner);
    if (starts_with(owner, "##Tooltip") || starts_with(owner, "##Popup")) continue;  // over the windows by design
    list_glyphs(l, n, table, scrolls(owner), glyphs);
  }
  LayoutReport r;
  r.glyphs = static_cast<int>(glyphs.size());
  for (const Glyph& g : glyphs)
    if (g.cut) r.clipped.push_back({owners[static_cast<std::size_t>(g.list)], line_text(glyphs, g), g.x0, g.y0});
  std::vector<std::size_t> order(glyphs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return glyphs[i].x0 < glyphs[j].x0; });
  for (std::size_t a = 0; a < order.size(); ++a) {  // sweep along x
    const Glyph& g = glyphs[order[a]];
    for (std::size_t b = a + 1; b < order.size() && glyphs[order[b]].x0 < g.x1; ++b) {
      const Glyph& o = glyphs[order[b]];
      // within one window: the tiled windows do not overlap, and a dialog lies over them by design
      if (o.list != g.list || !overlap(g, o)) continue;
      r.overlapping.push_back({owners[static_cast<std::size_t>(g.list)], line_text(glyphs, g) + "  over  " + line_text(glyphs, o),
                               g.x0, g.y0});
    }
  }
  return r;
}

std::string layout_text(const LayoutReport& r, std::size_t max_listed) {
  std::string s = std::to_string(r.glyphs) + " glyphs, " + std::to_string(r.clipped.size()) + " clipped, " +
                  std::to_string(r.overlapping.size()) + " overlapping";
  const auto list = [&](const std::vector<LayoutProblem>& ps, const char* what) {
    for (std::size_t i = 0; i < ps.size() && i < max_listed; ++i) {
      char at[48];
      std::snprintf(at, sizeof at, " at (%.0f, %.0f)", ps[i].x, ps[i].y);
      s += std::string("\n  ") + what + " in " + ps[i].window + at + ": \"" + ps[i].text + "\"";
    }
  };
  list(r.clipped, "clipped");
  list(r.overlapping, "overlap");
  return s;
}

}  // namespace sph::gui
