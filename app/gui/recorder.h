// Recording: the frames the stepper marks (record_index >= 0, at fixed simulated-time intervals) are
// rendered off-screen at a fixed size and written as dir/frame_00000.png, frame_00001.png, ... - the
// same names, size and renderer as the headless `sph run --frames`. A folder that holds frames already
// (a recording stopped or killed before) is continued after its last frame, never overwritten.
#pragma once
#include <string>
#include <vector>

#include "particle_view.h"

namespace sph::gui {

class Recorder {
 public:
  /// Creates the directory, removes what a killed recording left half-written (frame_*.tmp.PID) and
  /// numbers on after its last frame_NNNNN.png; false with *err if it cannot.
  bool start(const std::string& dir, std::string* err);
  void stop() { active_ = false; }
  bool active() const { return active_; }
  /// Renders and writes the next frame.
  bool write(ParticleView& view, const render::FrameScene& scene, const render::ViewSettings& settings, int width,
             int height, std::string* err);
  int frames() const { return frames_; }  ///< written since start()
  int first() const { return first_; }    ///< the number of the first of them
  const std::string& dir() const { return dir_; }

 private:
  bool active_ = false;
  std::string dir_;
  int first_ = 0, frames_ = 0;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace sph::gui
