#include "gui_state.h"

#include "sph/param_table.h"

namespace sph::gui {

GuiState::GuiState(Stepper& stepper, const RunConfig& initial)
    : edit(initial.params), values(initial.values), stepper_(stepper),
      scene_name_(initial.scene ? initial.scene->name : std::string()) {
  view.percentile_lo = 1.f;  // an outlier no longer squeezes every other particle into one colour
  view.percentile_hi = 99.f;
}

void GuiState::update() {
  const StepperFrame* f = stepper_.latest();
  fresh_ = f != nullptr && f->serial != serial_;
  frame_ = f;
  if (!fresh_) return;
  serial_ = f->serial;
  if (awaiting_ != 0 && f->params_version >= awaiting_) {
    awaiting_ = 0;
    if (message.rfind("loading ", 0) == 0) message.clear();  // done
  }
  if (f->error != last_error_) {  // a failed build or a refused scene value (divergence has its dialog)
    last_error_ = f->error;
    if (!f->error.empty() && !f->diverged) notify(f->error, true);
  }
  if (f->notice != last_notice_) {  // a state saved or loaded
    last_notice_ = f->notice;
    if (!f->notice.empty()) notify(f->notice);
  }
  if (f->config.scene) scene_name_ = f->config.scene->name;
  if (resync_version_ != 0 && f->params_version >= resync_version_) {
    resync_from(*f);
    resync_version_ = 0;
  } else if (f->world_serial != world_serial_) {
    values = f->config.values;  // a rebuild we did not start from here
  }
  ring.push(*f);                       // pause and scrub (snapshot_ring.h)
  if (f->running) scrub = -1;          // playing shows the live run
  if (f->world_serial != world_serial_) {
    world_serial_ = f->world_serial;
    scrub = -1;
    // Colour by a field this scene has (the renderer would fall back anyway, with a warning).
    if (f->snapshot.find(view.color_by) == nullptr && !f->snapshot.fields.empty())
      view.color_by = f->snapshot.find("rho") ? "rho" : f->snapshot.fields.front().name;
  }
}

const StepperFrame* GuiState::shown_frame() const {
  if (scrub >= 0 && static_cast<std::size_t>(scrub) < ring.size()) return &ring.at(static_cast<std::size_t>(scrub));
  return frame_;
}

void GuiState::resync_from(const StepperFrame& f) {
  edit = f.config.params;
  values = f.config.values;
}

void GuiState::post_live() {
  Params p = edit;
  if (frame_ != nullptr) {
    std::string err;
    for (const ParamInfo& info : param_table())
      if (!info.live) info.set(p, info.get(frame_->config.params), err);  // keep until reset
  }
  stepper_.post_params(p);
}

std::vector<std::string> GuiState::pending() const {
  std::vector<std::string> out;
  if (frame_ == nullptr) return out;
  for (const ParamInfo& info : param_table()) {
    if (info.live) continue;
    const std::string now = info.get(frame_->config.params), next = info.get(edit);
    if (now != next) out.push_back(std::string(info.key) + "  " + now + " -> " + next);
  }
  for (const auto& [name, v] : values) {
    const auto it = frame_->config.values.find(name);
    if (it == frame_->config.values.end() || it->second != v) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "scene.%s  %g -> %g", name.c_str(),
                    it == frame_->config.values.end() ? 0.0 : it->second, v);
      out.emplace_back(buf);
    }
  }
  return out;
}

void GuiState::reset() {
  if (frame_ == nullptr) return;
  RunConfig cfg = frame_->config;
  cfg.params = edit;
  cfg.values = values;
  awaiting_ = cfg.values == frame_->config.values ? stepper_.reset(edit) : stepper_.load(cfg);
}

void GuiState::load(const RunConfig& cfg) {
  edit = cfg.params;
  values = cfg.values;
  resync_version_ = awaiting_ = stepper_.load(cfg);
  if (cfg.scene) scene_name_ = cfg.scene->name;
  if (pause_at > 0.0) set_pause_at(0.0);
}

void GuiState::set_real_time_factor(double f) {
  real_time_factor = f;
  stepper_.set_real_time_factor(f);
}

void GuiState::resume() {
  const StepperFrame* f = frame();
  if (f && f->at_end && stop_at_end) {
    reset();  // a run that stopped at t_end starts again and runs (the stepper resumes a rebuilt World)
    return;
  }
  stepper_.resume();
}

void GuiState::set_stop_at_end(bool on) {
  stop_at_end = on;
  stepper_.set_stop_at_end(on);
}

void GuiState::set_tree_probe(std::int64_t k) {
  tree_probe = k;
  if (k >= 0) tree_probe_pick = static_cast<int>(k);
  stepper_.set_tree_probe(k);
}

void GuiState::inspect(std::int64_t id) {
  inspect_id = id;
  stepper_.set_inspect(id);
}

void GuiState::notify(std::string text, bool error) {
  message = std::move(text);
  message_is_error = error;
}

bool GuiState::open_file(const std::string& path) {
  try {
    load(RunConfig::load(path));
  } catch (const std::exception& e) {
    notify(e.what(), true);
    return false;
  }
  notify("loading " + path);
  if (recent && !recent->add(path) && !recent->error().empty()) notify(recent->error(), true);
  return true;
}

}  // namespace sph::gui
