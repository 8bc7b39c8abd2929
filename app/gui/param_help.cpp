#include "param_help.h"

#include <cstdio>

namespace sph::gui {
namespace {

std::string range_text(double lo, double hi) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "range: [%g, %g]", lo, hi);
  return buf;
}

std::string or_dimensionless(std::string_view unit) { return unit.empty() ? "dimensionless" : std::string(unit); }

}  // namespace

std::string param_unit_line(const ParamInfo& info) {
  if (!info.choices.empty()) {
    std::string s = "one of:";
    for (const std::string& c : info.choices) s += " " + c;
    return s;
  }
  return "unit: " + or_dimensionless(info.unit) + "    " + range_text(info.min, info.max) +
         (info.integer ? ", integer" : "");
}

std::string scene_value_help(const SceneParam& sp) {
  return "scene." + sp.name + ": " + sp.description + "\nunit: " + or_dimensionless(sp.unit) + "    " +
         range_text(sp.min, sp.max) + (sp.integer ? ", integer" : "") +
         "\nneeds reset: the particles are placed again (Enter, then Reset)";
}

}  // namespace sph::gui
