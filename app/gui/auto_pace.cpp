#include "auto_pace.h"

#include <cstdio>

#include "gui_state.h"

namespace sph::gui {

void AutoPace::see(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (!enabled_ || !f || s.building()) return;
  if (replay_ && f->world_serial != world_) replay_ = false;  // a new World: it runs at the pace
  if (replay_ && f->at_end && s.real_time_factor == paced_) {  // the pace came after the run had ended
    replay_ = false;
    s.resume();  // at t_end: replays from t = 0
    return;
  }
  if (f->config.scene->name != scene_) {  // a new scene: decide again
    scene_ = f->config.scene->name;
    decided_ = false;
  }
  if (decided_) return;
  if (s.real_time_factor > 0.0) {  // the user's pace
    decided_ = true;
    return;
  }
  const double t_end = f->config.params.time.t_end, t = f->snapshot.t;
  const auto steps = static_cast<double>(f->snapshot.step);
  if (f->world_serial != rate_world_) rate_world_ = f->world_serial, rate_ = 0.0;
  if (f->steps_per_second > 0.0) rate_ = f->steps_per_second;  // the last rate measured in this World
  if (!f->at_end && (steps < 20 || !(rate_ > 0.0))) return;     // too early to say
  decided_ = true;
  if (!(t > 0.0) || !(t_end > 0.0)) return;
  // predicted wall time to t_end [s]; a run that ended before any rate was shown took less than the
  // program's first frames
  const double wall = rate_ > 0.0 ? steps / rate_ * (t_end / t) : 0.0;
  if (wall >= kShortRun) return;
  paced_ = t_end / kPacedRun;
  s.set_real_time_factor(paced_);
  replay_ = true;
  world_ = f->world_serial;
  // decided late (slow first frames: a loaded machine, a sanitizer build) with the run already well on:
  // replay it from t = 0 at the pace rather than show its last part slowed
  if (!f->at_end && t > kLateFraction * t_end) s.reset();
}

std::string AutoPace::note(const GuiState& s) const {
  if (paced_ <= 0.0 || s.real_time_factor != paced_) return "";
  char b[160];
  std::snprintf(b, sizeof b, "slowed: t_end in %.0f s (%.3g sim s/s; Run: untick 'real time' for full speed)", kPacedRun,
                paced_);
  return b;
}

}  // namespace sph::gui
