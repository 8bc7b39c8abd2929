// The stepper's "save state": a checkpoint of the World it owns, in the format of `sph run
// --checkpoint-every` (sph/checkpoint.h), so `sph resume` and the GUI's "load state" read it.
#include "engine_loop.h"
#include "sph/checkpoint.h"

namespace sph::detail {

void EngineLoop::save_state(const std::string& path) {
  if (!world_) {
    error_ = "save state: no scene is loaded";
    return;
  }
  Checkpoint ck;
  ck.config_json = world_->config().to_json();
  ck.run_options = "{\"program\":\"sph-gui\"}";
  ck.world = world_->save_state();
  const std::string err = write_checkpoint(path, ck);
  if (err.empty()) notice_ = "saved state to " + path + " (t = " + std::to_string(world_->time()) + ")";
  else error_ = "save state: " + err;
}

}  // namespace sph::detail
