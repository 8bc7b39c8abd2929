// Fuzzes the command line's value parsers: --size WIDTHxHEIGHT, --range LO:HI (and pLO:HI), --cut AXIS=VALUE and the
// comma-separated --values list. Accepted values must be what they claim (positive sizes that print and
// parse back the same, finite ranges and numbers); refused ones must be refused cleanly.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli_common.h"
#include "frame_size.h"
#include "value_parsers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  int w = 0, h = 0;
  if (sph::render::parse_frame_size(text, &w, &h)) {
    if (w <= 0 || h <= 0) std::abort();
    int w2 = 0, h2 = 0;  // the canonical form parses back to the same size
    if (!sph::render::parse_frame_size(std::to_string(w) + "x" + std::to_string(h), &w2, &h2) || w2 != w || h2 != h)
      std::abort();
    if (!(sph::cli::frame_memory_bytes(w, h) > 0.0)) std::abort();
  }
  float lo = 0, hi = 0;
  if (sph::cli::parse_range(text, &lo, &hi) && !(std::isfinite(lo) && std::isfinite(hi))) std::abort();
  int axis = -1;
  float at = 0;
  if (sph::cli::parse_cut(text, &axis, &at) && !(axis >= 0 && axis <= 2 && std::isfinite(at))) std::abort();
  try {
    for (double v : sph::cli::parse_number_list(text, "--values"))
      if (!std::isfinite(v)) std::abort();
  } catch (const sph::ConfigError&) {
  }
  return 0;
}
