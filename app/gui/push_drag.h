// The right-drag push on a 2D plane view, without ImGui: the mouse in world coordinates becomes the
// engine's push (sph/push.h). The mouse's velocity on screen [length per wall second] is turned into
// simulated units by the pace the engine runs at (simulated time per wall second, measured from the
// frames), so the particles follow the mouse as the lecturer sees it move.
#pragma once
#include <cstdint>

#include "sph/push.h"

namespace sph {
struct Snapshot;
}

namespace sph::gui {

struct PushDrag {
  float radius = 0.f;      ///< R [length]; 0 = automatic (auto_push_radius)
  float tau = 0.f;         ///< relaxation time [time]; 0 = automatic (auto_push_tau)
  bool held = false;       ///< the right button went down over the plane and is still down
  double x = 0.0, y = 0.0;     ///< the mouse [length]
  double vx = 0.0, vy = 0.0;   ///< its smoothed velocity [length per wall second]
  double wall = -1.0;          ///< wall clock of that sample [s] (< 0: none yet)
  double rate = 0.0;           ///< simulated time per wall second, smoothed (0: unknown or paused)
  double rate_t = -1.0, rate_wall = 0.0;  ///< the last frame time seen and when
  std::uint64_t world = 0;     ///< world_serial the push was last sent to
  Push sent;                   ///< what was last sent
  double R = 0.0, T = 0.0;     ///< radius [length] and tau [time] of the drag in progress
  double vmax = 0.0;           ///< its speed limit [length/time] (0: 4 R / tau)
};

/// A tenth of the smaller side of the snapshot's box [length].
double auto_push_radius(const Snapshot& snap);
/// 20 of the engine's current steps dt [time]; before the first step (dt = 0) t_end / 1000.
double auto_push_tau(double dt, double t_end);
/// The drag's speed limit [length/time]: 0.3 cfl h / dt, three tenths of the signal speed the step's
/// Courant condition implies (dt = cfl h / c: about Mach 0.3, so a fast mouse on a slowly running scene
/// does not tear the fluid apart); 0 when dt or h is not known.
double auto_push_vmax(double dt, double cfl, double h);
/// Measures the pace from the frame time t [time] at wall time `wall` [s]; a run that stands still for
/// half a second has pace 0.
void see_frame_time(PushDrag& d, double t, double wall);
/// The mouse at (x, y) [length] at wall time `wall` [s]; starts a drag when `start`.
void move_mouse(PushDrag& d, double x, double y, double wall, bool start);
/// The push the drag asks for with radius R [length] and tau [time]: centred on the mouse, dragging at
/// its velocity in simulated units (0 while the pace is unknown), at most d.vmax (if set) and 4 R / tau.
Push drag_push(const PushDrag& d, double R, double tau);

}  // namespace sph::gui
