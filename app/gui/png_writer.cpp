#include "png_writer.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // private copy: no clash with another user of stb in the binary
#include <stb/stb_image_write.h>

namespace sph::gui {

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba,
               std::string* err) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (rgba.size() < n * 4) {
    *err = "write_png: image buffer too small";
    return false;
  }
  std::vector<std::uint8_t> rgb(n * 3);  // frames are opaque: drop alpha
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
  if (!stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3)) {
    *err = "could not write " + path;
    return false;
  }
  return true;
}

}  // namespace sph::gui
