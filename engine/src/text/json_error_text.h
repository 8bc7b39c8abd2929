// A JSON library error as a reader's message: nlohmann's "[json.exception.parse_error.101] parse error at
// line 2, column 1: ..." without its bracketed identifier, which says nothing to someone fixing a file.
#pragma once
#include <exception>
#include <string>

namespace sph {

inline std::string json_error_text(const std::exception& e) {
  std::string s = e.what();
  if (s.starts_with("[json.exception.")) {
    const std::size_t k = s.find("] ");
    if (k != std::string::npos) s.erase(0, k + 2);
  }
  return s;
}

}  // namespace sph
