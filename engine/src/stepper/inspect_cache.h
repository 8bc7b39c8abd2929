// The inspection frames carry (StepperFrame::inspection): Report::inspect costs about one evaluation (1.7
// steps of box_random at 20k particles, 0.18 s), so while the run steps it is refreshed at most every
// kInspectEvery seconds and so that it takes at most a tenth of the engine's time; a paused run is
// inspected once per state.
#pragma once
#include <chrono>
#include <cstdint>
#include <algorithm>
#include <optional>

#include "sph/world.h"

namespace sph::detail {

class InspectCache {
 public:
  static constexpr double kInspectEvery = 0.25;  ///< [s] of wall time
  void set_id(std::int64_t id) {
    id_ = id;
    value_.reset();
  }
  std::int64_t id() const { return id_; }
  /// The inspection of `w` (nullptr: none), recomputed when the state changed and it is due. `world`
  /// and `params` identify the World and the params it runs (a rebuild or a posted edit changes them).
  const std::optional<Inspection>& refresh(const World* w, std::uint64_t world, std::uint64_t params, bool running) {
    if (id_ < 0 || w == nullptr) {
      value_.reset();
      return value_;
    }
    const auto now = std::chrono::steady_clock::now();
    const bool mine = world_ == world && params_ == params;
    const bool same = value_ && mine && value_->step == w->steps() && value_->t == w->time();
    const double since = std::chrono::duration<double>(now - at_).count();
    const bool due = !running || !mine || since >= std::max(kInspectEvery, 9.0 * cost_);
    if (!same && due) {
      try {
        value_ = w->report().inspect(id_);
      } catch (const std::exception&) {  // an h solve that cannot finish on the copy: nothing to show
        value_.reset();
      }
      at_ = std::chrono::steady_clock::now();
      cost_ = std::chrono::duration<double>(at_ - now).count();
      world_ = world;
      params_ = params;
    }
    return value_;
  }

 private:
  std::int64_t id_ = -1;
  std::optional<Inspection> value_;
  std::uint64_t world_ = 0, params_ = 0;  // which World and params the value belongs to
  std::chrono::steady_clock::time_point at_{};
  double cost_ = 0.0;  // wall time of the last inspection [s]
};

}  // namespace sph::detail
