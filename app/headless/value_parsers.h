// Strict parsers of the frame flags' values (whole text, finite numbers) and the memory a frame takes;
// small and free of GL so the fuzz targets (tests/fuzz) link them alone.
#pragma once
#include <string>

namespace sph::cli {

/// "LO:HI" -> lo, hi: two finite numbers (float range) and nothing else; false otherwise.
bool parse_range(const std::string& text, float* lo, float* hi);
/// "AXIS=VALUE" (--cut) -> axis 0, 1, 2 for x, y, z and a finite float value; false otherwise.
bool parse_cut(const std::string& text, int* axis, float* at);
/// Memory one frame of width x height pixels takes while it is rendered and written [bytes]: the
/// off-screen colour and depth buffers, the read-back RGBA, the buffer handed to the PNG thread, the RGB
/// copy and the PNG (about 24 bytes a pixel).
double frame_memory_bytes(int width, int height);

}  // namespace sph::cli
