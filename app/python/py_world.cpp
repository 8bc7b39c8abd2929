#include "py_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sph/checkpoint.h"
#include "sph/key_value.h"
#ifdef SPH_HAVE_FRAMES
#include "offscreen_renderer.h"
#else
namespace sph::cli {
class OffscreenRenderer {};  // a build without the headless renderer: render() refuses
}  // namespace sph::cli
#endif

namespace sph::py {
namespace {

/// What the checkpoint's "run options" section holds for a state saved from Python.
constexpr const char* kRunOptions = R"({"writer": "sphsandbox"})";

void apply(RunConfig& cfg, const std::vector<std::pair<std::string, std::string>>& overrides) {
  for (const auto& [key, value] : overrides) cfg.set(key, value, "set " + key + "=" + value);
}

}  // namespace

PyWorld::PyWorld(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& overrides) {
  RunConfig cfg = RunConfig::load(scene);
  apply(cfg, overrides);
  cfg.validate();
  world_ = std::make_unique<World>(cfg);
}

PyWorld::~PyWorld() = default;

std::unique_ptr<PyWorld> PyWorld::load_state(const std::string& path) {
  const Checkpoint ck = read_checkpoint(path);
  RunConfig cfg = RunConfig::from_json_text(ck.config_json, "checkpoint " + path);
  cfg.validate();
  if (cfg.to_json() != ck.config_json)
    throw CheckpointError("checkpoint " + path + ": its scene resolves to other parameters in this build");
  std::unique_ptr<PyWorld> w(new PyWorld());
  w->world_ = std::make_unique<World>(cfg);
  w->world_->restore_state(ck.world, "checkpoint " + path);
  return w;
}

void PyWorld::step(double dt_max) {
  ++generation_;
  world_->step(dt_max);
}

void PyWorld::run_to(double t) {
  if (!std::isfinite(t) || t < world_->time())
    throw ConfigError("run_to: t = " + std::to_string(t) + ": expected a finite time not before the world's (" +
                      std::to_string(world_->time()) + ")");
  ++generation_;
  // the steps of `sph run --until t` (cli_run.cpp): each at most to the next output time (a multiple of
  // time.dt_out, else of t_end) or t, an output time counting as reached within 1e-12; so a run from
  // Python and `sph run` are the same bit for bit
  const Params& prm = world_->params();
  const double every = prm.time.dt_out > 0.0 ? prm.time.dt_out : prm.time.t_end;
  auto reached = [&](double when) { return world_->time() >= when * (1.0 - 1e-12); };
  long next = 1;
  while (every > 0.0 && reached(static_cast<double>(next) * every)) ++next;
  while (world_->time() < t) {
    const double target = every > 0.0 ? std::min(t, static_cast<double>(next) * every) : t;
    world_->step(target - world_->time());
    while (every > 0.0 && reached(static_cast<double>(next) * every)) ++next;
    if (reached(t) && t < prm.time.t_end) break;  // an output time; at t_end sph run steps until time >= t_end
  }
  world_->check_output();
}

void PyWorld::save_state(const std::string& path) const {
  Checkpoint ck{world_->config().to_json(), kRunOptions, world_->save_state(), ""};
  const std::string err = write_checkpoint(path, ck);
  if (!err.empty()) throw CheckpointError("checkpoint " + path + ": " + err);
}

void PyWorld::set_params(const std::vector<std::pair<std::string, std::string>>& overrides) {
  for (const auto& kv : overrides)
    if (kv.first.rfind("scene.", 0) == 0)
      throw ConfigError("set_params: " + kv.first + " is a scene value: it takes a new World(scene, set=...)");
  RunConfig cfg = world_->config();
  apply(cfg, overrides);
  cfg.validate();
  ++generation_;
  world_->set_params(cfg.params);
}

cli::OffscreenRenderer& PyWorld::renderer() {
#ifdef SPH_HAVE_FRAMES
  if (!renderer_) {
    std::string err;
    renderer_ = cli::OffscreenRenderer::create(&err);
    if (!renderer_) throw std::runtime_error("render: no off-screen OpenGL context: " + err);
  }
  return *renderer_;
#else
  throw std::runtime_error("render: this build has no headless renderer (SPH_BUILD_HEADLESS_RENDER=OFF)");
#endif
}

}  // namespace sph::py
