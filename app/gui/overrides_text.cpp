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

std::vector<std::string> split_values(const std::string& text) {
  std::vector<std::string> out;
  for (std::string item : split_overrides(text)) {
    std::string cur;
    for (const char c : item + " ") {
      if (c == ' ' || c == '\t') {
        if (!cur.empty()) out.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
  }
  return out;
}

bool split_sweep(const std::string& text, std::string* key, std::vector<std::string>* values, std::string* err) {
  const auto eq = text.find('=');
  *key = eq == std::string::npos ? std::string() : text.substr(0, eq);
  *values = eq == std::string::npos ? std::vector<std::string>{} : split_values(text.substr(eq + 1));
  if (key->empty() || values->empty()) {
    *err = "'" + text + "' is not KEY=V1,V2,... (e.g. kernel.eta=1.0,1.5)";
    return false;
  }
  return true;
}

}  // namespace sph::gui
