// PNG encoding (stb_image_write with zlib's deflate, the "up" filter, alpha dropped) and atomic PNG files.
#include "png_file.h"

#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "error_out.h"
#include "sph/atomic_file.h"

// stb_image_write's own deflate is ~4x slower than zlib at its fastest level, which compresses these
// frames (flat backgrounds) about as well: hand stb zlib's compress2. The buffer must come from malloc
// (stb frees it with STBIW_FREE).
static unsigned char* sph_png_deflate(unsigned char* data, int length, int* out_length, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (out == nullptr || compress2(out, &size, data, static_cast<uLong>(length), Z_BEST_SPEED) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(size);
  return out;
}

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // private copy: no clash with another user of stb in the same binary
#define STBIW_ZLIB_COMPRESS sph_png_deflate
#include <stb/stb_image_write.h>

namespace sph::cli {

std::string encode_png(int width, int height, const std::vector<std::uint8_t>& rgba) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (width <= 0 || height <= 0 || rgba.size() < n * 4) return {};
  // The "up" filter for every row: as small as stb's per-row search on these frames, at half the time.
  static std::once_flag tuned;
  std::call_once(tuned, [] { stbi_write_force_png_filter = 2; });
  std::vector<std::uint8_t> rgb(n * 3);  // frames are opaque: drop alpha (smaller, faster files)
  for (std::size_t i = 0; i < n; ++i) {
    rgb[3 * i] = rgba[4 * i];
    rgb[3 * i + 1] = rgba[4 * i + 1];
    rgb[3 * i + 2] = rgba[4 * i + 2];
  }
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3)) return {};
  return png;
}

bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba,
               std::string* err, sph::OutputManifest* manifest) {
  const std::string png = encode_png(width, height, rgba);
  if (png.empty()) {
    fail(err, "cannot write " + path + ": the image cannot be encoded");
    return false;
  }
  const std::string e = manifest ? manifest->write(std::filesystem::path(path).filename().string(), png)
                                 : sph::write_file_atomic(path, png);
  if (!e.empty()) {
    fail(err, e);
    return false;
  }
  return true;
}

}  // namespace sph::cli
