#include "png_writer.h"

#include "sph/atomic_file.h"

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
  std::string png;  // encoded in memory, then written atomically (a kill leaves no partial PNG)
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3)) {
    *err = "cannot write " + path + ": the image cannot be encoded";
    return false;
  }
  *err = sph::write_file_atomic(path, png);
  return err->empty();
}

}  // namespace sph::gui
