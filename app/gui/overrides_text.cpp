#include "overrides_text.h"

namespace sph::gui {

std::vector<std::string> split_overrides(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  auto flush = [&] {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
    item.clear();
  };
  for (const char c : text) {
    if (c == ',' || c == '\n' || c == ';') flush();
    else item += c;
  }
  flush();
  return out;
}

}  // namespace sph::gui
