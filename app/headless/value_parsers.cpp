#include "value_parsers.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace sph::cli {
namespace {

/// text[begin, end) as a finite float: the whole of it, no spaces.
bool parse_float(const std::string& text, std::size_t begin, std::size_t end, float* out) {
  if (begin >= end || std::isspace(static_cast<unsigned char>(text[begin]))) return false;
  const std::string part = text.substr(begin, end - begin);
  char* stop = nullptr;
  errno = 0;
  const double v = std::strtod(part.c_str(), &stop);
  if (stop != part.c_str() + part.size() || errno == ERANGE || !std::isfinite(v) ||
      std::fabs(v) > std::numeric_limits<float>::max())
    return false;
  *out = static_cast<float>(v);
  return true;
}

}  // namespace

bool parse_range(const std::string& text, float* lo, float* hi) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) return false;
  return parse_float(text, 0, colon, lo) && parse_float(text, colon + 1, text.size(), hi);
}

bool parse_cut(const std::string& text, int* axis, float* at) {
  static const std::string kAxes = "xyz";
  if (text.size() < 3 || text[1] != '=' || kAxes.find(text[0]) == std::string::npos) return false;
  if (!parse_float(text, 2, text.size(), at)) return false;
  *axis = static_cast<int>(kAxes.find(text[0]));
  return true;
}

double frame_memory_bytes(int width, int height) {
  return 24.0 * static_cast<double>(width) * static_cast<double>(height);
}

}  // namespace sph::cli
