// PNG files from RGBA8 pixels (rows top-down), written as RGB like the headless frames (stb_image_write).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sph::gui {

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba,
               std::string* err);

}  // namespace sph::gui
