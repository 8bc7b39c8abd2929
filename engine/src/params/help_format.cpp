// The layout of values in the help texts (params/help_format.h).
#include "params/help_format.h"

#include <charconv>
#include <cstdio>

namespace sph::help_format {

std::string pad(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string shown(const std::string& value) {
  double v = 0.0;
  if (!parse_number(value, v)) return value;
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string unit_of(std::string_view unit) { return unit.empty() ? "dimensionless" : std::string(unit); }

std::string value_space(const ParamInfo& info) {
  if (!info.choices.empty()) {
    std::string s = "one of";
    for (const std::string& c : info.choices) s += " " + c;
    return s;
  }
  return unit_of(info.unit) + ", range [" + number(info.min) + ", " + number(info.max) + "]" +
         (info.integer ? ", integer" : "");
}

}  // namespace sph::help_format
