#include "scene_text.h"

#include <cctype>
#include <cstdio>
#include <vector>

namespace sph::gui {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool number_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }

/// Positions of `word` in `text` as a whole number (no digit or point on either side).
std::vector<std::size_t> number_at(const std::string& text, const std::string& word) {
  std::vector<std::size_t> at;
  for (std::size_t p = text.find(word); p != std::string::npos; p = text.find(word, p + 1)) {
    const bool left = p == 0 || !number_char(text[p - 1]);
    const std::size_t end = p + word.size();
    // a sentence's full stop after the number is not part of it
    const bool right = end == text.size() || !number_char(text[end]) ||
                       (text[end] == '.' && (end + 1 == text.size() || !number_char(text[end + 1])));
    if (left && right) at.push_back(p);
  }
  return at;
}

}  // namespace

std::string describe_scene(const SceneSpec& spec, const SceneValues& values) {
  std::string text = spec.description, rest;
  for (const SceneParam& sp : spec.params) {
    const auto it = values.find(sp.name);
    if (it == values.end() || it->second == sp.value) continue;
    const std::string was = number(sp.value), now = number(it->second);
    bool shared = false;  // another value has the same default: the number is ambiguous
    for (const SceneParam& other : spec.params) shared |= &other != &sp && number(other.value) == was;
    const std::vector<std::size_t> at = number_at(text, was);
    if (!shared && at.size() == 1) {
      text.replace(at.front(), was.size(), now);
    } else {
      rest += (rest.empty() ? "" : ", ") + sp.name + " = " + now;
    }
  }
  return rest.empty() ? text : text + " (here " + rest + ")";
}

std::string scene_file_hint(const std::string& scene) { return "assets/scenes/" + scene + ".json"; }

}  // namespace sph::gui
