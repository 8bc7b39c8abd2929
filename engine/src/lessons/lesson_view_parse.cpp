// A lesson step's "view" (sph::LessonView), every key checked (lesson_json.h):
//   {"color_by": "vx", "panels": ["rho", "v"], "log": false, "profile_axis": "x", "range": [0, 1.2],
//    "zoom": [0.5, 0.5, 2], "cut": "z=0", "residuals": true}
#include <cctype>
#include <cstdlib>

#include "lesson_json.h"

namespace sph::lessons {
namespace {

bool flag_of(const json& j, const char* key, const std::string& origin, const std::string& p) {
  if (!j[key].is_boolean()) fail(origin, p + "." + key, "must be true or false");
  return j[key].get<bool>();
}

/// A list of n finite numbers.
std::vector<double> numbers_of(const json& j, const char* key, std::size_t n, const char* what,
                               const std::string& origin, const std::string& p) {
  const json& v = j[key];
  std::vector<double> out;
  if (v.is_array() && v.size() == n)
    for (const json& x : v)
      if (x.is_number() && std::isfinite(x.get<double>())) out.push_back(x.get<double>());
  if (out.size() != n) fail(origin, p + "." + key, std::string("must be ") + what);
  return out;
}

/// "AXIS=VALUE" with AXIS x, y or z and a finite VALUE -> axis 0..2 and the value; false otherwise.
bool parse_cut(const std::string& c, int* axis, double* at) {
  if (c.size() < 3 || (c[0] != 'x' && c[0] != 'y' && c[0] != 'z') || c[1] != '=') return false;
  const char* start = c.c_str() + 2;
  char* end = nullptr;
  const double v = std::strtod(start, &end);
  if (end == start || *end != '\0' || !std::isfinite(v)) return false;
  *axis = c[0] - 'x';
  *at = v;
  return true;
}

}  // namespace

LessonView view_of(const json& obj, const std::string& origin, const std::string& path) {
  LessonView v;
  if (!obj.contains("view")) return v;
  const json& j = obj["view"];
  const std::string p = path + "view";
  if (!j.is_object()) fail(origin, p, "must be an object");
  only_keys(j, {"color_by", "panels", "log", "profile_axis", "range", "zoom", "cut", "residuals"}, origin, p);
  v.color_by = text_of(j, "color_by", false, origin, p + ".");
  if (j.contains("panels")) {
    if (!j["panels"].is_array()) fail(origin, p + ".panels", "must be a list of fields ([]: the colour-by field alone)");
    v.panels.emplace();
    for (const json& f : j["panels"]) {
      if (!f.is_string() || f.get<std::string>().empty()) fail(origin, p + ".panels", "every panel must name a field");
      v.panels->push_back(f.get<std::string>());
    }
  }
  if (j.contains("log")) v.log = flag_of(j, "log", origin, p) ? 1 : 0;
  if (j.contains("residuals")) v.residuals = flag_of(j, "residuals", origin, p) ? 1 : 0;
  v.profile_axis = text_of(j, "profile_axis", false, origin, p + ".");
  if (!v.profile_axis.empty() && v.profile_axis != "off" && v.profile_axis != "x" && v.profile_axis != "y" &&
      v.profile_axis != "r")
    fail(origin, p + ".profile_axis", "'" + v.profile_axis + "' is not one of off, x, y, r (as --profile-axis)");
  if (j.contains("range")) {
    const std::vector<double> r = numbers_of(j, "range", 2, "[min, max] with min < max", origin, p);
    if (!(r[0] < r[1])) fail(origin, p + ".range", "must be [min, max] with min < max");
    v.range = std::make_pair(r[0], r[1]);
  }
  if (j.contains("zoom")) {
    const std::vector<double> z = numbers_of(j, "zoom", 3, "[centre x, centre y, zoom] with zoom > 0", origin, p);
    if (!(z[2] > 0.0)) fail(origin, p + ".zoom", "must be [centre x, centre y, zoom] with zoom > 0");
    v.zoom = std::array<double, 3>{z[0], z[1], z[2]};
  }
  const std::string cut = text_of(j, "cut", false, origin, p + ".");
  if (!cut.empty() && !parse_cut(cut, &v.cut_axis, &v.cut_at))
    fail(origin, p + ".cut", "'" + cut + "' is not AXIS=VALUE with AXIS x, y or z (as --cut), e.g. z=0");
  return v;
}

}  // namespace sph::lessons
