// Scene files and overrides: validated completely before a run writes anything.
#include "sph/config.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sph/hdf5_ic.h"
#include "sph/param_table.h"
#include "sph/suggest.h"

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
    throw ConfigError(path + ": malformed JSON: " + e.what());
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
  if (looks_like_file || (!find_scene(name_or_file) && std::filesystem::exists(name_or_file)))
    return from_file(name_or_file);
  return from_scene(name_or_file);
}

void RunConfig::set(const std::string& key, const std::string& value, const std::string& origin) {
  if (key.starts_with("scene.")) {
    const std::string name = key.substr(6);
    for (const auto& sp : scene->params) {
      if (sp.name != name) continue;
      double v = 0.0;
      if (!parse_number(value, v)) throw ConfigError(origin + ": key '" + key + "': '" + value + "' is not a number");
      if (sp.integer && v != std::floor(v))  // (a cast of 1e30 to an integer is undefined)
        throw ConfigError(origin + ": key '" + key + "': '" + value + "' is not an integer");
      if (v < sp.min || v > sp.max)
        throw ConfigError(origin + ": key '" + key + "' = " + value + " is out of range [" + std::to_string(sp.min) +
                          ", " + std::to_string(sp.max) + "]");
      values[name] = v;
      return;
    }
    std::string known;
    std::vector<std::string> keys;
    for (const auto& sp : scene->params) {
      known += " scene." + sp.name;
      keys.push_back("scene." + sp.name);
    }
    throw ConfigError(origin + ": unknown key '" + key + "' for scene " + scene->name + did_you_mean(key, keys) +
                      (known.empty() ? std::string(" (it has no scene.* keys)") : " (its keys:" + known + ")"));
  }
  const ParamInfo* info = find_param(key);
  if (!info) {
    std::vector<std::string> keys;
    for (const auto& p : param_table()) keys.emplace_back(p.key);
    for (const auto& sp : scene->params) keys.push_back("scene." + sp.name);
    throw ConfigError(origin + ": unknown key '" + key + "'" + did_you_mean(key, keys) +
                      " (`sph params` lists every run parameter, `sph help " + scene->name + "` the scene's keys)");
  }
  std::string err;
  if (!info->set(params, value, err)) throw ConfigError(origin + ": key '" + key + "': " + err);
  explicit_keys[std::string(info->key)] = origin;
}

void check_physics(const SceneSpec& scene, const Physics& physics) {
  for (const SlotInfo& s : slot_table()) {
    const std::string option = physics.get(s.slot);
    if (scene.allows(s.slot, option)) continue;
    std::string list;
    for (const auto& o : scene.allowed[static_cast<std::size_t>(s.slot)]) list += (list.empty() ? "" : ", ") + o;
    if (list.empty()) list = "none (it has no self-gravity: gravity needs an open domain)";
    throw ConfigError("physics." + std::string(s.key) + " = " + option + ": scene " + scene.name + " takes only " +
                      list);
  }
  const std::string combo = physics.validate();
  if (!combo.empty()) throw ConfigError(combo);
}

void RunConfig::validate() const {
  try {
    check_physics(*scene, params.physics);
  } catch (const ConfigError& e) {
    // name where the first slot the message mentions was set (a file or a --set), if it was
    const std::string msg = e.what();
    std::string where;
    std::size_t first = std::string::npos;
    for (const auto& [key, origin] : explicit_keys) {
      if (!key.starts_with("physics.")) continue;
      const std::size_t at = msg.find(key + " =");
      if (at != std::string::npos && at < first) { first = at; where = origin + ": "; }
    }
    throw ConfigError(where + msg);
  }
  for (const auto& [key, origin] : explicit_keys) {
    const ParamInfo* info = find_param(key);
    if (info->is_active(params)) continue;
    const std::string shown = "'" + key + "'" + (info->alias.empty() ? "" : " (formerly '" + std::string(info->alias) + "')");
    std::string why = ", which scene " + scene->name + " does not run";
    if (info->slot != Slot::Count)
      why += " (physics." + std::string(slot_info(info->slot).key) + " = " + params.physics.get(info->slot) + ")";
    throw ConfigError(origin + ": key " + shown + " is a parameter of " + std::string(info->stage) + why);
  }
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
