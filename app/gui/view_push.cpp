#include "view_push.h"

#include <imgui.h>

#include <algorithm>

#include "camera.h"
#include "sph/snapshot.h"

namespace sph::gui {
namespace {

/// Ends a push in progress.
void release(GuiState& s) {
  PushDrag& d = s.push;
  if (!d.held) return;
  d.held = false;
  d.wall = -1.0;
  s.set_push(Push{});
  d.sent = Push{};
}

}  // namespace

void push_particles(GuiState& s, const ParticleView& view, const Rect& r) {
  PushDrag& d = s.push;
  const StepperFrame* f = s.frame();
  const ImGuiIO& io = ImGui::GetIO();
  const double wall = ImGui::GetTime();
  if (f) see_frame_time(d, f->snapshot.t, wall);
  const bool plane = f && f->snapshot.dim == 2 && s.view.profile_axis < 0 && !f->comparing && s.scrub < 0 && !s.building();
  if (!plane || !ImGui::IsMouseDown(ImGuiMouseButton_Right)) return release(s);
  const Snapshot& snap = f->snapshot;
  // world <-> framebuffer pixels of the view (relative to r) from the last frame's mapping (linear, equal aspect)
  const render::FrameLayout& L = view.layout();
  const render::Bounds b = render::view_bounds(snap);
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  if (!L.to_pixel(b[0], b[2], 0.f, &x0, &y0) || !L.to_pixel(b[1], b[3], 0.f, &x1, &y1) || x1 == x0 || y1 == y0)
    return release(s);
  const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
  const float mx = io.MousePos.x * sx - r.x, my = io.MousePos.y * sy - r.y;
  const bool start = !d.held;
  if (start) {  // only a press on the plot starts a push
    if (io.WantCaptureMouse || !ImGui::IsMouseClicked(ImGuiMouseButton_Right) || !L.plot.contains(mx, my)) return;
    d.held = true;
    d.R = d.radius > 0.f ? d.radius : auto_push_radius(snap);
    d.T = d.tau > 0.f ? d.tau : auto_push_tau(f->diagnostics.dt, f->config.params.time.t_end);
    double h = 0.0;  // the fluid's largest smoothing length
    for (std::size_t i = 0; i < snap.h.size(); ++i)
      if (!snap.is_wall(i)) h = std::max(h, static_cast<double>(snap.h[i]));
    d.vmax = auto_push_vmax(f->diagnostics.dt, f->config.params.time.cfl, h);
  }
  const double ppw = (x1 - x0) / (b[1] - b[0]);  // framebuffer pixels per length
  const double wx = b[0] + (mx - x0) * (b[1] - b[0]) / (x1 - x0), wy = b[2] + (my - y0) * (b[3] - b[2]) / (y1 - y0);
  move_mouse(d, wx, wy, wall, start);
  const Push p = drag_push(d, d.R, d.T);
  if (p != d.sent || d.world != f->world_serial) {
    s.set_push(p);
    d.sent = p;
    d.world = f->world_serial;
  }
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImVec2 c(io.MousePos.x, io.MousePos.y);
  dl->AddCircle(c, static_cast<float>(d.R * ppw) / sx, IM_COL32(255, 255, 255, 220), 64, 2.f);
  dl->AddCircleFilled(c, 3.f, IM_COL32(255, 255, 255, 220));
  ImGui::SetTooltip("push: R = %.3g, tau = %.3g, v = (%.3g, %.3g), |v| <= %.3g", d.R, d.T, p.v[0], p.v[1],
                    d.vmax > 0.0 ? std::min(d.vmax, 4.0 * d.R / d.T) : 4.0 * d.R / d.T);
}

bool window_pos_of_world(const ParticleView& view, const Rect& r, double x, double y, float* wx, float* wy) {
  float px = 0, py = 0;
  if (!view.layout().to_pixel(static_cast<float>(x), static_cast<float>(y), 0.f, &px, &py)) return false;
  const ImGuiIO& io = ImGui::GetIO();
  *wx = (r.x + px) / io.DisplayFramebufferScale.x;
  *wy = (r.y + py) / io.DisplayFramebufferScale.y;
  return true;
}

}  // namespace sph::gui
