#include "particle_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "camera.h"
#include "sph/snapshot.h"
#include "window.h"

namespace sph::gui {

bool same_view(const render::ViewSettings& a, const render::ViewSettings& b) {
  const auto& c = a.camera2d;
  const auto& d = b.camera2d;
  const auto& o = a.orbit;
  const auto& q = b.orbit;
  return a.color_by == b.color_by && a.cmap == b.cmap && a.auto_range == b.auto_range && a.percentile_lo == b.percentile_lo &&
         a.percentile_hi == b.percentile_hi && a.log_scale == b.log_scale && a.auto_log == b.auto_log &&
         a.cut_axis == b.cut_axis && a.cut_at == b.cut_at && a.show_trails == b.show_trails && a.show_tree == b.show_tree &&
         a.range_min == b.range_min && a.range_max == b.range_max && c.fit == d.fit && c.center_x == d.center_x &&
         c.center_y == d.center_y && c.zoom == d.zoom && o.yaw_deg == q.yaw_deg && o.pitch_deg == q.pitch_deg &&
         o.distance == q.distance && o.zoom == q.zoom && o.fov_deg == q.fov_deg && o.up_axis == q.up_axis &&
         a.size_mode == b.size_mode && a.h_scale == b.h_scale && a.point_px == b.point_px &&
         a.min_radius_px == b.min_radius_px && a.show_exact == b.show_exact && a.show_walls == b.show_walls &&
         a.show_outlines == b.show_outlines && a.profile_axis == b.profile_axis && a.text_scale == b.text_scale &&
         a.panels == b.panels && a.residuals == b.residuals && a.high_contrast == b.high_contrast;
}

bool ParticleView::init(std::string* err) { return renderer_.init(&Window::get_proc, err); }

void ParticleView::interact(const Rect& r, const sph::Snapshot& snap, render::ViewSettings* view) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;
  const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
  const float mx = io.MousePos.x * sx, my = io.MousePos.y * sy;
  const render::FrameLayout& L = renderer_.last_layout();
  const bool over = r.contains(mx, my) && L.plot.contains(mx - r.x, my - r.y);
  const bool dragging = ImGui::IsMouseDragging(ImGuiMouseButton_Left) && r.contains(io.MouseClickedPos[0].x * sx,
                                                                                       io.MouseClickedPos[0].y * sy);
  if (over && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    view->camera2d = render::Camera2D{};
    view->orbit = render::OrbitCamera{};
    return;
  }
  if (snap.dim == 3) {
    if (dragging) {
      view->orbit.yaw_deg -= 0.3f * io.MouseDelta.x;
      view->orbit.pitch_deg = std::clamp(view->orbit.pitch_deg + 0.3f * io.MouseDelta.y, -89.f, 89.f);
    }
    if (over && io.MouseWheel != 0.f) view->orbit.zoom = std::clamp(view->orbit.zoom * std::pow(1.15f, io.MouseWheel), 0.05f, 50.f);
    return;
  }
  if (snap.dim != 2 || view->profile_axis >= 0) return;  // profiles (1D, or 2D against x or y) fit themselves
  // World units per pixel from the last frame's mapping (equal aspect).
  const render::Bounds b = render::view_bounds(snap);
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  if (!L.to_pixel(b[0], b[2], 0.f, &x0, &y0) || !L.to_pixel(b[1], b[2], 0.f, &x1, &y1) || x1 == x0) return;
  const float wpp = (b[1] - b[0]) / (x1 - x0);
  auto& cam = view->camera2d;
  auto unfit = [&] {
    if (!cam.fit) return;
    cam.fit = false;
    cam.center_x = 0.5f * (b[0] + b[1]);
    cam.center_y = 0.5f * (b[2] + b[3]);
  };
  if (dragging && (io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f)) {
    unfit();
    cam.center_x -= io.MouseDelta.x * sx * wpp;
    cam.center_y += io.MouseDelta.y * sy * wpp;
  }
  if (over && io.MouseWheel != 0.f) {
    unfit();
    // Keep the world point under the cursor in place.
    const float cx = r.x + L.plot.x + 0.5f * L.plot.w, cy = r.y + L.plot.y + 0.5f * L.plot.h;
    const float wx = cam.center_x + (mx - cx) * wpp, wy = cam.center_y - (my - cy) * wpp;
    const float old_zoom = cam.zoom;
    cam.zoom = std::clamp(cam.zoom * std::pow(1.15f, io.MouseWheel), 0.05f, 500.f);
    const float wpp2 = wpp * old_zoom / cam.zoom;
    cam.center_x = wx - (mx - cx) * wpp2;
    cam.center_y = wy + (my - cy) * wpp2;
  }
}

bool ParticleView::stale(std::uint64_t serial, const render::ViewSettings& view, const render::Highlight& highlight,
                         const Rect& r) const {
  if (!drawn_ || !same_view(view, drawn_view_) || !(highlight == drawn_highlight_) ||
      target_.width() != static_cast<int>(r.w) || target_.height() != static_cast<int>(r.h))
    return true;
  const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - drawn_at_).count();
  return serial != drawn_serial_ && since >= std::max(min_interval_, 3.0 * render_cost_);
}

void ParticleView::draw(const render::FrameScene& scene, std::uint64_t serial, const render::ViewSettings& view,
                        const Rect& r, int fb_height) {
  const int w = static_cast<int>(r.w), h = static_cast<int>(r.h);
  if (w <= 0 || h <= 0) return;
  const bool redraw = stale(serial, view, scene.highlight, r);
  std::string err;
  if (!target_.resize(w, h, &err)) return;
  if (redraw) {
    const auto t0 = std::chrono::steady_clock::now();
    target_.bind();
    renderer_.render(scene, view, w, h);
    ViewTarget::finish();  // so that the cost below includes the rasterisation
    ViewTarget::unbind();
    drawn_ = true;
    drawn_at_ = std::chrono::steady_clock::now();
    const double cost = std::chrono::duration<double>(drawn_at_ - t0).count();
    render_cost_ = render_cost_ > 0.0 ? 0.8 * render_cost_ + 0.2 * cost : cost;
    drawn_serial_ = serial;
    drawn_step_ = scene.a ? static_cast<long long>(scene.a->step) : -1;
    drawn_t_ = scene.a ? scene.a->t : 0.0;
    drawn_view_ = view;
    drawn_highlight_ = scene.highlight;
  }
  target_.blit_to_window(static_cast<int>(r.x), static_cast<int>(r.y), fb_height);
}

bool ParticleView::render_rgba(const render::FrameScene& scene, const render::ViewSettings& view, int width,
                               int height, std::vector<std::uint8_t>* rgba, std::string* err) {
  if (!record_target_.resize(width, height, err)) return false;
  record_target_.bind();
  renderer_.render(scene, view, width, height);
  record_target_.read_rgba(rgba);
  ViewTarget::unbind();
  drawn_ = false;  // the renderer's last layout now belongs to the recorded frame
  return true;
}

std::optional<render::Picked> ParticleView::particle_under_mouse(const Rect& r) const {
  if (!drawn_) return std::nullopt;  // the renderer's last frame is not the one on screen
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
  const float mx = io.MousePos.x * sx - r.x, my = io.MousePos.y * sy - r.y;
  if (mx < 0.f || my < 0.f || mx >= r.w || my >= r.h) return std::nullopt;
  return renderer_.pick(mx, my, 6.f * sx);
}

std::optional<std::array<float, 2>> ParticleView::window_pos_of(int run, std::uint32_t index, const Rect& r) const {
  if (!drawn_) return std::nullopt;
  const auto p = renderer_.pixel_of(run, index);
  if (!p) return std::nullopt;
  const ImGuiIO& io = ImGui::GetIO();
  return std::array<float, 2>{(r.x + (*p)[0]) / io.DisplayFramebufferScale.x, (r.y + (*p)[1]) / io.DisplayFramebufferScale.y};
}

}  // namespace sph::gui
