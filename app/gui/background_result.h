// A result computed on a thread of its own beside the engine (a convergence study, a lesson's check):
// started once, polled every frame by its panel, and waited for when it is dropped (a run cannot be
// interrupted). An exception thrown by the work becomes an error message.
#pragma once
#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <string>
#include <utility>

namespace sph::gui {

template <class T>
class BackgroundResult {
 public:
  BackgroundResult() = default;
  BackgroundResult(const BackgroundResult&) = delete;
  BackgroundResult& operator=(const BackgroundResult&) = delete;
  ~BackgroundResult() {
    if (future_.valid()) future_.wait();
  }

  /// Starts `work` (a callable returning T) on its own thread.
  template <class Work>
  void start(Work&& work) {
    future_ = std::async(std::launch::async, std::forward<Work>(work));
  }
  /// Collects the result once the thread has finished; true while still running.
  bool poll() {
    if (!future_.valid()) return false;
    if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
    try {
      result_ = future_.get();
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    return false;
  }
  /// Blocks until the work has finished, then collects it.
  void wait() {
    if (future_.valid()) future_.wait();
    poll();
  }
  const std::optional<T>& result() const { return result_; }
  const std::string& error() const { return error_; }

 private:
  std::future<T> future_;
  std::optional<T> result_;
  std::string error_;
};

}  // namespace sph::gui
