// The Python module's world: an engine World built from a scene name or file with key=value overrides,
// stepped from Python, saved and loaded as checkpoints (the format of `sph run --checkpoint-every`), and
// an off-screen renderer made on the first render. Errors are the engine's exceptions; module.cpp turns
// them into Python exceptions.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/world.h"

namespace sph::cli {
class OffscreenRenderer;
}

namespace sph::py {

class PyWorld {
 public:
  /// RunConfig::load(scene) with the overrides applied in order (keys as for `sph run --set`), validated:
  /// throws ConfigError naming the key.
  PyWorld(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& overrides);
  /// A world taking over a checkpoint file's state (CheckpointError names the file).
  static std::unique_ptr<PyWorld> load_state(const std::string& path);
  ~PyWorld();

  /// One step (at most dt_max) [time].
  void step(double dt_max);
  /// Steps until time t exactly as `sph run --until t` does (each step at most to the next output time,
  /// every time.dt_out), then its output checks (a gravity scene's energy; DivergedError on a blow-up).
  void run_to(double t);
  /// Writes the whole state to `path` (CheckpointError when it cannot be written).
  void save_state(const std::string& path) const;
  /// Adopts run-parameter overrides from the next step on (World::set_params; ConfigError keeps the old).
  void set_params(const std::vector<std::pair<std::string, std::string>>& overrides);

  World& world() { return *world_; }
  const World& world() const { return *world_; }
  /// The off-screen renderer, made on first use (the error names the GL backend that failed).
  cli::OffscreenRenderer& renderer();

  /// Bumped whenever the storage may move (a step, a parameter change): views taken before are stale.
  long generation() const { return generation_; }

 private:
  PyWorld() = default;

  std::unique_ptr<World> world_;
  std::unique_ptr<cli::OffscreenRenderer> renderer_;
  long generation_ = 0;
};

}  // namespace sph::py
