// Run-parameter overrides and their checks: RunConfig::set (a key of the parameter table or the
// scene's, from a scene file or a --set), check_physics and RunConfig::validate. Reading scene files
// is in io/config.cpp.
#include "sph/config.h"

#include <cmath>

#include "sph/param_table.h"
#include "sph/suggest.h"
#include "text/number_text.h"

namespace sph {

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
        throw ConfigError(origin + ": key '" + key + "' = " + value + " is out of range [" + exact_text(sp.min) + ", " +
                          exact_text(sp.max) + "]");
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

}  // namespace sph
