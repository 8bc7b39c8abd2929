#include "inbox.h"

#include <utility>

namespace sph::detail {

std::uint64_t Inbox::post_params(const Params& p) {
  std::uint64_t v = 0;
  {
    std::lock_guard lock(mutex_);
    params_ = p;
    v = ++version_;
  }
  wake_.notify_one();
  return v;
}

void Inbox::push(Command c) {
  {
    std::lock_guard lock(mutex_);
    commands_.push_back(std::move(c));
  }
  wake_.notify_one();
}

std::uint64_t Inbox::push_with_params(Command c, const Params& p) {
  std::uint64_t v = 0;
  {
    std::lock_guard lock(mutex_);
    params_ = p;
    v = c.params_version = ++version_;
    commands_.push_back(std::move(c));
  }
  wake_.notify_one();
  return v;
}

void Inbox::request_stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
}

bool Inbox::stop_requested() {
  std::lock_guard lock(mutex_);
  return stop_;
}

InboxBatch Inbox::take(std::uint64_t adopted) {
  InboxBatch b;
  std::lock_guard lock(mutex_);
  b.commands.swap(commands_);
  b.stop = stop_;
  seen_ = version_;
  if (version_ > adopted) {
    b.has_params = true;
    b.params = params_;
    b.params_version = version_;
  }
  return b;
}

void Inbox::wait() {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return pending(); });
}

void Inbox::wait_until(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  wake_.wait_until(lock, deadline, [this] { return pending(); });
}

}  // namespace sph::detail
