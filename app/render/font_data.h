// The overlay font's TrueType file (DejaVu Sans Mono, Debian fonts-dejavu-core), embedded into the binary
// at build time (CMakeLists.txt generates font_data.cpp from font_data.cpp.in), so that programs draw text
// without reading a font file at run time. The font's bytes are never part of the source tree.
#pragma once
#include <span>

namespace sph::render {

/// The bytes of the embedded .ttf file.
std::span<const unsigned char> overlay_font_ttf();

}  // namespace sph::render
