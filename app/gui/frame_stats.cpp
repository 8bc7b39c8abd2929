#include "frame_stats.h"

#include <thread>

namespace sph::gui {

void FrameStats::frame_done(bool drawn) {
  Clock::time_point now = Clock::now();
  if (max_fps_ > 0.0 && frames_ > 0) {
    const auto due = last_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / max_fps_));
    if (now < due) {
      std::this_thread::sleep_until(due);
      now = Clock::now();
    }
  }
  if (frames_ == 0) first_ = window_start_ = now;
  if (drawn && frames_ > 0) ++drawn_;  // like frames_: the first frame starts the clock
  ++frames_;
  ++window_frames_;
  window_drawn_ += drawn ? 1 : 0;
  const double window = std::chrono::duration<double>(now - window_start_).count();
  if (window >= 1.0) {
    fps_ = static_cast<double>(window_frames_) / window;
    drawn_fps_ = static_cast<double>(window_drawn_) / window;
    window_frames_ = window_drawn_ = 0;
    window_start_ = now;
  }
  last_ = now;
}

double FrameStats::seconds() const { return frames_ > 0 ? std::chrono::duration<double>(last_ - first_).count() : 0.0; }

double FrameStats::mean_fps() const {
  const double s = seconds();
  return s > 0.0 ? static_cast<double>(frames_ - 1) / s : 0.0;
}

double FrameStats::mean_drawn_fps() const {
  const double s = seconds();
  return s > 0.0 ? static_cast<double>(drawn_) / s : 0.0;
}

}  // namespace sph::gui
