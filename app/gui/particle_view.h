// The particle view: the shared renderer drawing the latest snapshot into an off-screen target that
// is blitted into its place in the window. The target is redrawn only when the snapshot, the view
// settings or the size change, so the display keeps its frame rate however slowly the engine steps.
// Mouse: 2D drag pans and the wheel zooms about the cursor; 3D drag orbits and the wheel zooms;
// double-click fits the view again.
#pragma once
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "frame_scene.h"
#include "layout.h"
#include "renderer.h"
#include "view_settings.h"
#include "view_target.h"

namespace sph {
struct Snapshot;
}

namespace sph::gui {

class ParticleView {
 public:
  /// New snapshots are drawn at most max_hz times a second (0 = no limit), and so that drawing the view
  /// takes at most a third of the time: a software rasteriser spends ~15 ms on a 0.75 Mpx profile, and
  /// the panels must keep their frame rate while the engine publishes 100 snapshots a second. Changes
  /// of the view settings or size are drawn at once (pan, zoom and orbit stay immediate).
  explicit ParticleView(double max_hz = 60.0) : min_interval_(max_hz > 0.0 ? 1.0 / max_hz : 0.0) {}
  /// Loads GL through glfwGetProcAddress and builds the renderer (context current).
  bool init(std::string* err);
  /// Mouse interaction over `r` (framebuffer px) when ImGui does not want the mouse.
  void interact(const Rect& r, const sph::Snapshot& snap, render::ViewSettings* view);
  /// The off-screen view would be redrawn by draw() (new snapshot, view settings, highlight or size).
  bool stale(std::uint64_t serial, const render::ViewSettings& view, const render::Highlight& highlight,
             const Rect& r) const;
  /// The view on screen was rendered from the snapshot `serial` (stale() is false for a newer snapshot
  /// too, until the rate limit allows its redraw).
  bool shows(std::uint64_t serial) const { return drawn_ && drawn_serial_ == serial; }
  /// Redraws if needed (serial identifies the snapshots) and blits into `r` of a window fb_height tall.
  void draw(const render::FrameScene& scene, std::uint64_t serial, const render::ViewSettings& view, const Rect& r,
            int fb_height);
  /// Renders the scene at width x height and reads it back (RGBA8, rows top-down): recording.
  bool render_rgba(const render::FrameScene& scene, const render::ViewSettings& view, int width, int height,
                   std::vector<std::uint8_t>* rgba, std::string* err);
  /// The particle under the mouse in the view drawn into `r` (framebuffer px), within a few pixels.
  std::optional<render::Picked> particle_under_mouse(const Rect& r) const;
  /// Where particle `index` of run 0 (A) or 1 (B) is on screen [window px, ImGui's mouse coordinates].
  std::optional<std::array<float, 2>> window_pos_of(int run, std::uint32_t index, const Rect& r) const;
  const render::FrameLayout& layout() const { return renderer_.last_layout(); }
  /// The text of the last picture drawn, with its boxes (layout checks).
  const std::vector<render::TextSpan>& texts() const { return renderer_.last_texts(); }
  /// Step and time of the snapshot the view on screen was rendered from (-1 before any).
  long long drawn_step() const { return drawn_step_; }
  double drawn_time() const { return drawn_t_; }

 private:
  render::Renderer renderer_;
  ViewTarget target_, record_target_;
  double min_interval_;      // [s], from max_hz
  double render_cost_ = 0.0; // smoothed wall time of one view render, GL finished [s]
  std::chrono::steady_clock::time_point drawn_at_{};
  std::uint64_t drawn_serial_ = 0;
  long long drawn_step_ = -1;
  double drawn_t_ = 0.0;
  render::ViewSettings drawn_view_;
  render::Highlight drawn_highlight_;
  bool drawn_ = false;
};

/// Memberwise equality of view settings (a change means the view must be redrawn).
bool same_view(const render::ViewSettings& a, const render::ViewSettings& b);

}  // namespace sph::gui
