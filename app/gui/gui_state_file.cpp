// GuiState's "save state" and "load state": checkpoint files (sph/checkpoint.h), the format `sph run
// --checkpoint-every` writes. The file is read and checked here; the engine thread builds the World
// from its configuration and takes over its state.
#include "gui_state.h"
#include "sph/checkpoint.h"

namespace sph::gui {

void GuiState::save_state(const std::string& path) {
  if (path.empty()) {
    notify("save state: give a file name", true);
    return;
  }
  stepper_.save_state(path);
}

bool GuiState::load_state(const std::string& path) {
  try {
    const Checkpoint ck = read_checkpoint(path);
    RunConfig cfg = RunConfig::from_json_text(ck.config_json, "checkpoint " + path);
    cfg.validate();
    if (cfg.to_json() != ck.config_json)
      throw CheckpointError("checkpoint " + path + ": its scene resolves to other parameters in this build");
    edit = cfg.params;
    values = cfg.values;
    resync_version_ = awaiting_ = stepper_.load_state(path, cfg, ck.world);
    if (cfg.scene) scene_name_ = cfg.scene->name;
    notify("loading state from " + path);
    return true;
  } catch (const std::exception& e) {
    notify(e.what(), true);
    return false;
  }
}

}  // namespace sph::gui
