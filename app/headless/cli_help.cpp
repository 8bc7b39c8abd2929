#include "cli_help.h"

#include <cstdio>

#include "cli_common.h"
#include "exit_codes.h"
#include "sph/help_text.h"

namespace sph::cli {

int help_command(const std::string& scene, const std::vector<std::string>& sets) {
  if (scene.empty()) {
    std::fputs(scenes_help().c_str(), stdout);
    return kOk;
  }
  try {
    RunConfig cfg = RunConfig::load(scene);
    apply_sets(cfg, sets);
    cfg.validate();
    std::fputs(scene_help(cfg).c_str(), stdout);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: help: %s\n", e.what());
    return kInvalidScene;
  }
  return kOk;
}

int params_command() {
  std::fputs(params_help().c_str(), stdout);
  return kOk;
}

}  // namespace sph::cli
