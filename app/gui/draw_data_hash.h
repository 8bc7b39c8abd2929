// A fingerprint of ImGui's draw data (vertices, indices, commands): equal fingerprints mean the panels
// would draw exactly the same pixels again, so the frame need not be redrawn (a software rasteriser
// then leaves the CPU to the engine).
#pragma once
#include <cstdint>

struct ImDrawData;

namespace sph::gui {

std::uint64_t draw_data_hash(const ImDrawData& d);

}  // namespace sph::gui
