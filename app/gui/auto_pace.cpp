#include "auto_pace.h"

#include <cstdio>

#include "gui_state.h"

namespace sph::gui {

void AutoPace::see(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (!enabled_ || !f || s.building()) return;
  if (f->config.scene->name != scene_) {  // a new scene: decide again
    scene_ = f->config.scene->name;
    decided_ = watching_ = false;
  }
  if (decided_) return;
  if (s.real_time_factor > 0.0) {  // the user's pace
    decided_ = true;
    return;
  }
  const double t_end = f->config.params.time.t_end, t = f->snapshot.t;
  const auto now = std::chrono::steady_clock::now();
  if (!watching_) {
    if (!f->running) return;
    watching_ = true;
    start_ = now;
    t0_ = t;
    return;
  }
  const double wall = std::chrono::duration<double>(now - start_).count();
  if (!f->at_end && wall < 0.25) return;
  decided_ = true;
  const double rate = (t - t0_) / wall;  // simulated time per wall second
  if (!(rate > 0.0) || !(t_end > t0_) || (t_end - t0_) / rate >= kShortRun) return;
  paced_ = t_end / kPacedRun;
  s.set_real_time_factor(paced_);
  if (f->at_end) s.resume();  // it ended already: replay it at the pace
}

std::string AutoPace::note(const GuiState& s) const {
  if (paced_ <= 0.0 || s.real_time_factor != paced_) return "";
  char b[160];
  std::snprintf(b, sizeof b, "slowed: t_end in %.0f s (%.3g sim s/s; Run: untick 'real time' for full speed)", kPacedRun,
                paced_);
  return b;
}

}  // namespace sph::gui
