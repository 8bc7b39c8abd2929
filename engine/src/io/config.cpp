// Scene files: a built-in scene, a JSON scene file or an HDF5 initial condition read into a RunConfig,
// and written back (to_json). Overrides and their checks are in params/run_config_set.cpp.
#include "sph/config.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sph/hdf5_ic.h"
#include "sph/param_table.h"
#include "sph/suggest.h"
#include "text/json_error_text.h"

namespace sph {

RunConfig RunConfig::from_scene(const std::string& name) {
  const SceneSpec* s = find_scene(name);
  if (!s) {
    std::string known;
    std::vector<std::string> names;
    for (const auto& sc : scene_registry()) {
      known += " " + sc.name;
      names.push_back(sc.name);
    }
    throw ConfigError("unknown scene '" + name + "'" + did_you_mean(name, names) + " (built-in scenes:" + known + ")");
  }
  RunConfig c;
  c.scene = s;
  c.params = s->defaults;
  c.values = s->default_values();
  return c;
}

RunConfig RunConfig::from_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ConfigError(path + ": is a directory, not a scene file");
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open scene file");
  std::stringstream text;
  text << in.rdbuf();
  return from_json_text(text.str(), path);
}

RunConfig RunConfig::from_json_text(const std::string& text, const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // syntax, invalid UTF-8, a number out of double range (1e400)
    throw ConfigError(path + ": malformed JSON: " + json_error_text(e));
  }
  if (!j.is_object()) throw ConfigError(path + ": the top level must be an object");
  for (const auto& [key, _] : j.items())
    if (key != "scene" && key != "params" && key != "description")
      throw ConfigError(path + ": unknown key '" + key + "' (expected scene, params, description)" +
                        did_you_mean(key, {"scene", "params", "description"}));
  if (!j.contains("scene") || !j["scene"].is_string())
    throw ConfigError(path + ": key 'scene' must name a built-in scene or an HDF5 initial condition");
  RunConfig c;
  try {
    const std::string scene = j["scene"].get<std::string>();
    c = is_hdf5_path(scene) ? load_hdf5_ic(scene) : from_scene(scene);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": key 'scene': " + e.what());
  }
  if (j.contains("params")) {
    if (!j["params"].is_object()) throw ConfigError(path + ": key 'params' must be an object");
    for (const auto& [key, value] : j["params"].items()) {
      std::string text;
      if (value.is_string()) text = value.get<std::string>();
      else if (value.is_number()) {
        std::ostringstream os;
        os.precision(17);
        os << value.get<double>();
        text = os.str();
      } else throw ConfigError(path + ": key 'params." + key + "' must be a number or a string");
      c.set(key, text, path);
    }
  }
  return c;
}

RunConfig RunConfig::load(const std::string& name_or_file) {
  if (is_hdf5_path(name_or_file)) return load_hdf5_ic(name_or_file);
  const bool looks_like_file = name_or_file.ends_with(".json") || name_or_file.find('/') != std::string::npos;
  std::error_code ec;  // a name the system refuses is not a file: from_scene names it as unknown
  if (looks_like_file || (!find_scene(name_or_file) && std::filesystem::exists(name_or_file, ec)))
    return from_file(name_or_file);
  return from_scene(name_or_file);
}

std::string RunConfig::to_json() const {
  nlohmann::ordered_json j;
  j["scene"] = source_file.empty() ? scene->name : source_file;
  nlohmann::ordered_json p = nlohmann::ordered_json::object();
  for (const auto& info : param_table()) {
    if (!info.is_active(params)) continue;
    const std::string v = info.get(params);
    double d = 0.0;
    if (info.choices.empty() && parse_number(v, d)) {
      if (info.integer) p[std::string(info.key)] = static_cast<long long>(d);
      else p[std::string(info.key)] = d;
    } else {
      p[std::string(info.key)] = v;
    }
  }
  for (const auto& sp : scene->params) {
    const double v = values.at(sp.name);
    if (sp.integer) p["scene." + sp.name] = static_cast<long long>(v);
    else p["scene." + sp.name] = v;
  }
  j["params"] = p;
  return j.dump(2) + "\n";
}

}  // namespace sph
