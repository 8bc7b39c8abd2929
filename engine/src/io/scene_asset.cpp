// The generated scene files (see sph/scene_asset.h).
#include "sph/scene_asset.h"

#include <nlohmann/json.hpp>

#include "sph/config.h"

namespace sph {

std::string scene_asset_json(const std::string& name) {
  const RunConfig cfg = RunConfig::from_scene(name);  // throws ConfigError for an unknown name
  const auto resolved = nlohmann::ordered_json::parse(cfg.to_json());
  nlohmann::ordered_json j;
  j["description"] = cfg.scene->description;
  j["scene"] = resolved.at("scene");
  j["params"] = resolved.at("params");
  return j.dump(2) + "\n";
}

}  // namespace sph
