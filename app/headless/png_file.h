// RGBA8 frames as RGB PNG files: encoded by stb_image_write with zlib's deflate, written atomically.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "sph/output_manifest.h"

namespace sph::cli {

/// An RGBA8 image (rows top-down) as the bytes of an RGB PNG; empty when it cannot be encoded.
std::string encode_png(int width, int height, const std::vector<std::uint8_t>& rgba);
/// Writes an RGBA8 image (rows top-down) as an RGB PNG, atomically (sph/atomic_file.h); with a manifest,
/// into its folder under path's file name and listed in its manifest.json.
bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba,
               std::string* err, sph::OutputManifest* manifest = nullptr);

}  // namespace sph::cli
