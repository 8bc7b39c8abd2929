#include "push_drag.h"

#include <algorithm>
#include <cmath>

#include "sph/snapshot.h"

namespace sph::gui {

double auto_push_radius(const Snapshot& snap) {
  const double wx = snap.bounds[1] - snap.bounds[0], wy = snap.bounds[3] - snap.bounds[2];
  const double side = std::min(wx > 0.0 ? wx : 1.0, wy > 0.0 ? wy : 1.0);
  return 0.1 * side;
}

double auto_push_tau(double dt, double t_end) {
  if (dt > 0.0) return 20.0 * dt;
  return std::isfinite(t_end) && t_end > 0.0 ? 1e-3 * t_end : 1e-3;
}

double auto_push_vmax(double dt, double cfl, double h) {
  return dt > 0.0 && cfl > 0.0 && h > 0.0 ? 0.3 * cfl * h / dt : 0.0;
}

void see_frame_time(PushDrag& d, double t, double wall) {
  if (d.rate_t < 0.0 || t < d.rate_t) {  // first frame, or a new World
    d.rate_t = t;
    d.rate_wall = wall;
    return;
  }
  const double dw = wall - d.rate_wall;
  if (t > d.rate_t && dw > 0.0) {
    const double r = (t - d.rate_t) / dw;
    d.rate = d.rate > 0.0 ? 0.7 * d.rate + 0.3 * r : r;
    d.rate_t = t;
    d.rate_wall = wall;
  } else if (dw > 0.5) {
    d.rate = 0.0;  // paused or stopped at t_end
  }
}

void move_mouse(PushDrag& d, double x, double y, double wall, bool start) {
  if (start || d.wall < 0.0) {
    d.vx = d.vy = 0.0;
  } else if (wall > d.wall) {
    const double dw = wall - d.wall;
    d.vx = 0.6 * d.vx + 0.4 * (x - d.x) / dw;  // smoothed over a few display frames
    d.vy = 0.6 * d.vy + 0.4 * (y - d.y) / dw;
  }
  d.x = x;
  d.y = y;
  d.wall = wall;
}

Push drag_push(const PushDrag& d, double R, double tau) {
  Push p;
  p.x = {d.x, d.y, 0.0};
  p.radius = R;
  p.tau = tau;
  if (d.rate > 0.0) {
    double vx = d.vx / d.rate, vy = d.vy / d.rate;
    const double v = std::hypot(vx, vy), vmax = d.vmax > 0.0 ? std::min(d.vmax, 4.0 * R / tau) : 4.0 * R / tau;
    if (v > vmax) {
      vx *= vmax / v;
      vy *= vmax / v;
    }
    p.v = {vx, vy, 0.0};
  }
  return p;
}

}  // namespace sph::gui
