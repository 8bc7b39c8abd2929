// A slower default play speed for scenes that would reach t_end in under a second of wall time (Sod runs
// to t = 0.2 in 0.2 s): they are paced to reach it in about 8 s, and the status line says so. Measured
// on the first 0.25 s of a scene's run at full speed (or on the whole run when it ends sooner, then it
// replays paced); decided once per scene, so a user's own pace (Run: real time x) is kept.
#pragma once
#include <chrono>
#include <string>

namespace sph::gui {

class GuiState;

class AutoPace {
 public:
  static constexpr double kShortRun = 1.0;  ///< [s] wall time to t_end below which a scene is paced
  static constexpr double kPacedRun = 8.0;  ///< [s] wall time to t_end when paced

  explicit AutoPace(bool enabled) : enabled_(enabled) {}
  /// Once per display frame: measures the run's speed and paces it when it is short.
  void see(GuiState& s);
  /// The status line's note while the pace set here is in force ("" otherwise).
  std::string note(const GuiState& s) const;

 private:
  bool enabled_;
  std::string scene_;           ///< the scene decided for
  bool decided_ = false;
  bool watching_ = false;
  std::chrono::steady_clock::time_point start_;
  double t0_ = 0.0;
  double paced_ = 0.0;          ///< the real-time factor set here (0: none)
};

}  // namespace sph::gui
