// Display frame rate: measured over 1 s windows (shown in the status line) and over the whole run
// (printed at exit), plus the optional cap that leaves the CPU to the engine thread. A frame is either
// drawn (rendered and swapped) or idle (nothing on screen would change, so the last picture stays).
#pragma once
#include <chrono>
#include <cstdint>

namespace sph::gui {

class FrameStats {
 public:
  using Clock = std::chrono::steady_clock;
  explicit FrameStats(double max_fps) : max_fps_(max_fps) {}

  /// Call once per frame of the main loop (after the swap, if drawn): counts it, sleeps to honour the cap.
  void frame_done(bool drawn);
  double fps() const { return fps_; }                ///< frames (drawn or idle) over the last 1 s window [1/s]
  double drawn_fps() const { return drawn_fps_; }    ///< drawn frames over the last 1 s window [1/s]
  std::int64_t frames() const { return frames_; }    ///< frames so far
  std::int64_t drawn() const { return drawn_; }      ///< drawn frames so far
  double seconds() const;                             ///< wall time since the first frame [s]
  double mean_fps() const;                            ///< frames after the first / seconds() [1/s]
  double mean_drawn_fps() const;                      ///< drawn frames after the first / seconds() [1/s]

 private:
  double max_fps_;
  Clock::time_point first_{}, window_start_{}, last_{};
  std::int64_t frames_ = 0, window_frames_ = 0, drawn_ = 0, window_drawn_ = 0;
  double fps_ = 0.0, drawn_fps_ = 0.0;
};

}  // namespace sph::gui
