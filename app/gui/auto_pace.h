// A slower default play speed for scenes that would reach t_end in under 4 s of wall time, too fast to
// watch (Sod runs to t = 0.2 in 0.2 s; about 1-2 s in a sanitizer build): they are paced to reach it in about 8 s, and the status line says so. The wall
// time is predicted from the engine's measured steps per second and the steps taken so far (first
// frame with 20 steps or at t_end); a run that reached t_end at full speed, or was past a tenth of it when
// paced, replays from t = 0 paced.
// Decided once per scene, so a user's own pace (Run: real time x) is kept.
#pragma once
#include <cstdint>
#include <string>

namespace sph::gui {

class GuiState;

class AutoPace {
 public:
  static constexpr double kShortRun = 4.0;  ///< [s] wall time to t_end below which a scene is paced
  static constexpr double kPacedRun = 8.0;  ///< [s] wall time to t_end when paced
  static constexpr double kLateFraction = 0.1;  ///< paced past this fraction of t_end: replayed from t = 0

  explicit AutoPace(bool enabled) : enabled_(enabled) {}
  /// Once per display frame: measures the run's speed and paces it when it is short.
  void see(GuiState& s);
  /// The status line's note while the pace set here is in force ("" otherwise).
  std::string note(const GuiState& s) const;

 private:
  bool enabled_;
  std::string scene_;           ///< the scene decided for
  bool decided_ = false;
  bool replay_ = false;         ///< paced: replay the run if it reaches t_end in the World it was paced in
  std::uint64_t world_ = 0;     ///< that World (StepperFrame::world_serial)
  double paced_ = 0.0;          ///< the real-time factor set here (0: none)
  std::uint64_t rate_world_ = 0;
  double rate_ = 0.0;           ///< the engine's last measured steps/s in World rate_world_
};

}  // namespace sph::gui
