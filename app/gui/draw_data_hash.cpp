#include "draw_data_hash.h"

#include <imgui.h>

namespace sph::gui {
namespace {

/// FNV-1a over raw bytes.
void mix(std::uint64_t& h, const void* data, std::size_t n) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= b[i];
    h *= 1099511628211ull;
  }
}

}  // namespace

std::uint64_t draw_data_hash(const ImDrawData& d) {
  std::uint64_t h = 1469598103934665603ull;
  mix(h, &d.DisplaySize, sizeof d.DisplaySize);
  for (int i = 0; i < d.CmdListsCount; ++i) {
    const ImDrawList* list = d.CmdLists[i];
    mix(h, list->VtxBuffer.Data, static_cast<std::size_t>(list->VtxBuffer.Size) * sizeof(ImDrawVert));
    mix(h, list->IdxBuffer.Data, static_cast<std::size_t>(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& c : list->CmdBuffer) {
      mix(h, &c.ClipRect, sizeof c.ClipRect);
      mix(h, &c.TextureId, sizeof c.TextureId);
      mix(h, &c.VtxOffset, sizeof c.VtxOffset);
      mix(h, &c.IdxOffset, sizeof c.IdxOffset);
      mix(h, &c.ElemCount, sizeof c.ElemCount);
    }
  }
  return h;
}

}  // namespace sph::gui
