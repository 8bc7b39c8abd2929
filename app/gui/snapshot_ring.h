// Pause and scrub: the last N frames the view showed (view-only copies: the snapshots of run A and B,
// the reference values and the labels; no history), kept in a ring so the time slider can step back
// through them while the run is paused. Cleared when a new World starts. At most 240 frames and at
// most kMaxBytes of particle data (fewer frames for large scenes).
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>

#include "sph/stepper.h"

namespace sph::gui {

class SnapshotRing {
 public:
  static constexpr std::size_t kMaxFrames = 240;
  static constexpr std::size_t kMaxBytes = std::size_t{512} << 20;  ///< particle data of all stored frames

  explicit SnapshotRing(std::size_t max_frames = kMaxFrames, std::size_t max_bytes = kMaxBytes)
      : max_frames_(max_frames), max_bytes_(max_bytes) {}
  /// Stores a copy of a frame the view showed (a new step of the current World; a frame of another World
  /// clears the ring first). The oldest frames go when the ring is full.
  void push(const StepperFrame& f);
  void clear();
  std::size_t size() const { return frames_.size(); }
  const StepperFrame& at(std::size_t k) const { return frames_[k]; }  ///< k = 0: the oldest
  std::size_t bytes() const { return bytes_; }

  /// Bytes of particle data of a frame (both runs' snapshots) [B].
  static std::size_t frame_bytes(const StepperFrame& f);

 private:
  std::size_t max_frames_, max_bytes_;
  std::deque<StepperFrame> frames_;
  std::size_t bytes_ = 0;
  std::uint64_t world_ = 0;
};

}  // namespace sph::gui
