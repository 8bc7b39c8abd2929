// The public face of the stepper: posts into the inbox (channels 1 and 2) and reads the triple buffer
// (channel 3); the engine thread runs EngineLoop.
#include "sph/stepper.h"

#include <atomic>
#include <thread>
#include <utility>

#include "engine_loop.h"

namespace sph {

using detail::Command;

namespace {
Command make(Command::Kind kind, double value = 0.0, bool flag = false) {
  Command c;
  c.kind = kind;
  c.value = value;
  c.flag = flag;
  return c;
}
}  // namespace

struct Stepper::Impl {
  detail::Inbox inbox;
  detail::TripleBuffer<StepperFrame> frames;
  std::atomic<std::uint64_t> published{0};
  bool have_front = false;  // reader side: front() holds a published frame
  std::thread thread;       // started last, joined first
};

Stepper::Stepper(const RunConfig& cfg, StepperOptions options) : impl_(std::make_unique<Impl>()) {
  Command load;
  load.kind = Command::Kind::Load;
  load.config = cfg;
  impl_->inbox.push_with_params(std::move(load), cfg.params);
  if (options.start_running) impl_->inbox.push(make(Command::Kind::Resume));
  Impl* d = impl_.get();
  d->thread = std::thread([d, options] {
    detail::EngineLoop loop(options, d->inbox, d->frames, d->published);
    loop.run();
  });
}

Stepper::~Stepper() {
  impl_->inbox.request_stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

std::uint64_t Stepper::post_params(const Params& p) { return impl_->inbox.post_params(p); }

std::uint64_t Stepper::reset(const Params& p) {
  Command c = make(Command::Kind::Reset);
  c.config.params = p;
  return impl_->inbox.push_with_params(std::move(c), p);
}

void Stepper::save_state(const std::string& path) {
  Command c = make(Command::Kind::SaveState);
  c.name = path;
  impl_->inbox.push(std::move(c));
}

std::uint64_t Stepper::load_state(const std::string& path, const RunConfig& cfg, const std::string& state) {
  Command c = make(Command::Kind::LoadState);
  c.name = path;
  c.config = cfg;
  c.state = state;
  return impl_->inbox.push_with_params(std::move(c), cfg.params);
}

std::uint64_t Stepper::load(const RunConfig& cfg) {
  Command c = make(Command::Kind::Load);
  c.config = cfg;
  return impl_->inbox.push_with_params(std::move(c), cfg.params);
}

void Stepper::pause() { impl_->inbox.push(make(Command::Kind::Pause)); }
void Stepper::resume() { impl_->inbox.push(make(Command::Kind::Resume)); }
void Stepper::step_once() { impl_->inbox.push(make(Command::Kind::StepOnce)); }

void Stepper::set_scene_value(const std::string& name, double value) {
  Command c = make(Command::Kind::SetSceneValue, value);
  c.name = name;
  impl_->inbox.push(std::move(c));
}

void Stepper::set_real_time_factor(double f) { impl_->inbox.push(make(Command::Kind::SetRealTimeFactor, f)); }
void Stepper::set_stop_at_end(bool on) { impl_->inbox.push(make(Command::Kind::SetStopAtEnd, 0.0, on)); }
void Stepper::set_pause_at(double t) { impl_->inbox.push(make(Command::Kind::SetPauseAt, t)); }
void Stepper::set_tree_probe(std::int64_t k) {
  impl_->inbox.push(make(Command::Kind::SetTreeProbe, static_cast<double>(k)));
}
void Stepper::set_record_interval(double every) {
  impl_->inbox.push(make(Command::Kind::SetRecordInterval, every));
}
void Stepper::set_compare(const std::vector<std::string>& overrides) {
  Command c = make(Command::Kind::SetCompare);
  c.names = overrides;
  impl_->inbox.push(std::move(c));
}
void Stepper::set_sweep(const std::string& key, const std::vector<std::string>& values) {
  Command c = make(Command::Kind::SetSweep);
  c.name = key;
  c.names = values;
  impl_->inbox.push(std::move(c));
}
void Stepper::set_inspect(std::int64_t id) { impl_->inbox.push(make(Command::Kind::SetInspect, static_cast<double>(id))); }

void Stepper::set_push(const Push& push) {
  Command c = make(Command::Kind::SetPush);
  c.push = push;
  impl_->inbox.push(std::move(c));
}

const StepperFrame* Stepper::latest() {
  if (impl_->frames.acquire()) impl_->have_front = true;
  return impl_->have_front ? &impl_->frames.front() : nullptr;
}

std::uint64_t Stepper::published() const { return impl_->published.load(std::memory_order_acquire); }

}  // namespace sph
