// What the particle view shows: colour by one of the snapshot's fields (only the fields the scene's
// stages allocate), the colour map, an automatic or fixed range, in 2D the plane or a profile against
// x or y, particle size, walls and reference outlines shown or hidden, and the camera.
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "colormap.h"
#include "profile_axis.h"
#include "profile_view.h"
#include "panels.h"
#include "sph/trail_log.h"

namespace sph::gui {

namespace {

// 2D: the plane, or a profile of the field against x, y or r; 3D: the particles or a profile against r
// (render::ViewSettings::profile_axis).
void panel_view_kind(render::ViewSettings& v, int dim) {
  struct Kind { const char* name; int axis; };
  const Kind k2[4] = {{"plane", -1}, {"profile against x", 0}, {"profile against y", 1},
                      {"profile against r", render::kRadialAxis}};
  const Kind k3[2] = {{"3D view", -1}, {"profile against r", render::kRadialAxis}};
  const Kind* kinds = dim == 2 ? k2 : k3;
  const int count = dim == 2 ? 4 : 2;
  int current = 0;
  for (int k = 0; k < count; ++k)
    if (kinds[k].axis == v.profile_axis) current = k;
  if (ImGui::BeginCombo("view", kinds[current].name)) {
    for (int k = 0; k < count; ++k)
      if (ImGui::Selectable(kinds[k].name, k == current)) v.profile_axis = kinds[k].axis;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("plane / 3D view: the particles where they are.\n"
                      "profile: the field (y axis) against x, y or the distance r from the origin, one dot per\n"
                      "fluid particle, with the scene's reference curve along that axis (hydrostatic pressure\n"
                      "against y, the Lane-Emden density against r).");
}

bool has_walls(const Snapshot& snap) {
  return std::any_of(snap.kind.begin(), snap.kind.end(), [](std::uint8_t k) { return k != 0; });
}

// Walls and reference outlines: greyed out when the snapshot has none.
void overlay_toggles(const Snapshot& snap, render::ViewSettings& v) {
  constexpr ImGuiHoveredFlags kEvenDisabled = ImGuiHoveredFlags_AllowWhenDisabled;
  ImGui::BeginDisabled(!has_walls(snap));
  ImGui::Checkbox("show walls", &v.show_walls);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(kEvenDisabled))
    ImGui::SetTooltip("Draw the wall (boundary) particles, in grey whatever the field; off hides them.\n"
                      "Profiles never show them. (Greyed out: this scene has no walls.)");
  if (snap.dim != 2) return;
  ImGui::SameLine();
  ImGui::BeginDisabled(snap.outlines.empty());
  ImGui::Checkbox("reference outline", &v.show_outlines);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(kEvenDisabled))
    ImGui::SetTooltip("Draw the scene's reference shapes over the particles in white, e.g. the exact ellipse\n"
                      "of the elliptical drop or the measured surge fronts of the dam break, with their labels.\n"
                      "(Greyed out: this scene has none.)");
}

// The right-drag push's radius R [length] and relaxation time tau [time]; 0 = automatic.
void push_settings(GuiState& s, const StepperFrame& f) {
  PushDrag& d = s.push;
  const double R = d.radius > 0.f ? d.radius : auto_push_radius(f.snapshot);
  const double tau = d.tau > 0.f ? d.tau : auto_push_tau(f.diagnostics.dt, f.config.params.time.t_end);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.f);
  float r = static_cast<float>(R);
  if (ImGui::DragFloat("push R", &r, static_cast<float>(0.01 * auto_push_radius(f.snapshot)), 0.f, 1e30f,
                       d.radius > 0.f ? "%.4g" : "%.4g (auto)"))
    d.radius = std::max(r, 0.f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Right drag on the plane pushes the fluid within R of the cursor [length]:\n"
                      "a = w(r/R) (v_mouse - v) / tau, w(q) = (1 - q^2)^2: the particles are dragged along with\n"
                      "the mouse. Auto: a tenth of the box's smaller side. 0 = auto.");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.f);
  float t = static_cast<float>(tau);
  if (ImGui::DragFloat("tau", &t, static_cast<float>(0.01 * tau), 0.f, 1e30f, d.tau > 0.f ? "%.4g" : "%.4g (auto)"))
    d.tau = std::max(t, 0.f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("How fast the pushed particles take the mouse's velocity [time]: smaller drags harder\n"
                      "(the step is then at most cfl x tau). Auto: 20 of the current steps. 0 = auto.");
  ImGui::SameLine();
  if (ImGui::SmallButton("auto##push")) d.radius = d.tau = 0.f;
}


/// The field coloured by (and plotted, in a profile), the colour map, the automatic range's percentiles.
void colour_controls(render::ViewSettings& v, const Snapshot& snap, const SnapshotField* shown, bool profile) {
  if (ImGui::BeginCombo(profile ? "plot / colour" : "colour by", shown ? shown->label.c_str() : v.color_by.c_str())) {
    for (const SnapshotField& fld : snap.fields)
      if (ImGui::Selectable(fld.label.c_str(), fld.name == v.color_by)) v.color_by = fld.name;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Fields this scene's physics stages allocate (profiles: also the y axis).\n"
                      "The automatic range is the fluid's: wall particles are always grey.");
  if (ImGui::BeginCombo("colour map", v.cmap.c_str())) {
    for (std::string_view name : render::colormap_names())
      if (ImGui::Selectable(std::string(name).c_str(), name == v.cmap)) v.cmap = std::string(name);
    ImGui::EndCombo();
  }
  if (ImGui::Checkbox("auto range", &v.auto_range) && !v.auto_range && shown) {
    v.range_min = shown->min;  // start the fixed range from what is shown now
    v.range_max = shown->max;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("On: every frame uses the percentiles below of the fluid's values (0..100: min..max;\n"
                      "1..99 keeps one outlier from turning every other particle one colour). Off: a fixed range.");
  if (v.auto_range) {
    float pct[2] = {v.percentile_lo, v.percentile_hi};
    if (ImGui::InputFloat2("percentiles", pct, "%.3g", ImGuiInputTextFlags_EnterReturnsTrue) && pct[0] >= 0.f &&
        pct[1] <= 100.f && pct[0] < pct[1]) {
      v.percentile_lo = pct[0];
      v.percentile_hi = pct[1];
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("low and high percentile of the automatic range [%%]");
    ImGui::SameLine();
    if (ImGui::SmallButton(v.percentile_lo > 0.f || v.percentile_hi < 100.f ? "min..max" : "1..99")) {
      const bool to_full = v.percentile_lo > 0.f || v.percentile_hi < 100.f;
      v.percentile_lo = to_full ? 0.f : 1.f;
      v.percentile_hi = to_full ? 100.f : 99.f;
    }
  }
}

/// Tree-gravity scenes in 2D and 3D: the cells one particle's Barnes-Hut walk opens.
void tree_cells_toggle(GuiState& s, const Snapshot& snap) {
  bool on = s.tree_probe >= 0;
  if (ImGui::Checkbox("tree cells", &on)) s.set_tree_probe(on ? s.tree_probe_pick : -1);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("What the Barnes-Hut tree opens for one particle (white ring) at the current theta:\n"
                      "blue cells act on it as one multipole each, amber leaves particle by particle.\n"
                      "Change gravity.theta and watch the cells shrink or grow.");
  if (on) {
    int k = s.tree_probe_pick;
    if (ImGui::InputInt("probe particle", &k)) s.set_tree_probe(std::clamp<std::int64_t>(k, 0, snap.count - 1));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Index of the particle whose tree walk is drawn (0..N-1)");
  }
}

/// Profiles: the exact curve, the rho, v, p, u panels, the dot size.
void profile_controls(render::ViewSettings& v, const Snapshot& snap) {
  if (!snap.exact.empty()) {
    ImGui::Checkbox("exact solution", &v.show_exact);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The scene's exact or reference curve of the plotted field along this axis, if it has one");
    ImGui::Checkbox("error strip", &v.residuals);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Under each panel, the values minus the exact curve at each particle: where the error is made.\n"
                        "A comparison (A/B) always has a strip: B - A in 1D.");
  }
  std::vector<std::string> four;  // rho, v, p, u: those this scene has
  for (const char* name : {"rho", "v", "p", "u"})
    if (snap.find(render::panel_fields(snap, {name}).front())) four.emplace_back(name);
  bool panels = !v.panels.empty();
  if (four.size() > 1 && ImGui::Checkbox("panels: rho, v, p, u", &panels)) v.panels = panels ? four : std::vector<std::string>{};
  if (four.size() > 1 && ImGui::IsItemHovered())
    ImGui::SetTooltip("One profile per field with its exact curve, as the seed documents show shock tubes;\n"
                      "the dots keep the colour of the colour-by field.");
  ImGui::SliderFloat("dot size", &v.point_px, 1.f, 8.f, "%.1f px");
}

/// 3D: the cutaway, an axis and the plane's place between the box's walls.
void cut_controls(const Snapshot& snap, render::ViewSettings& v) {
  static const char* const kAxes[] = {"no cut", "cut x", "cut y", "cut z"};
  int item = v.cut_axis + 1;
  ImGui::SetNextItemWidth(6.f * ImGui::GetFontSize());
  if (ImGui::Combo("##cut", &item, kAxes, 4)) v.cut_axis = item - 1;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Cutaway: draw only the particles on this side of a plane, so the inside shows");
  if (v.cut_axis < 0) return;
  const int a = std::clamp(v.cut_axis, 0, 2);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.f);
  ImGui::SliderFloat("##cut_at", &v.cut_at, snap.bounds[2 * a], snap.bounds[2 * a + 1], "keep <= %.3g");
}

/// The plane or 3D view: particle size, walls and outlines, the camera, the push's settings (2D).
void particle_controls(GuiState& s, const StepperFrame& f, render::ViewSettings& v) {
  const Snapshot& snap = f.snapshot;
  bool by_h = v.size_mode == render::SizeMode::Smoothing;
  if (ImGui::Checkbox("size from h", &by_h))
    v.size_mode = by_h ? render::SizeMode::Smoothing : render::SizeMode::Pixels;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.f);
  if (by_h)
    ImGui::SliderFloat("##hs", &v.h_scale, 0.05f, 2.f, "radius %.2f h");
  else
    ImGui::SliderFloat("##px", &v.point_px, 0.5f, 10.f, "radius %.1f px");
  overlay_toggles(snap, v);
  if (ImGui::Button("Fit view")) {
    v.camera2d = render::Camera2D{};
    v.orbit = render::OrbitCamera{};
  }
  ImGui::SameLine();
  ImGui::TextDisabled(snap.dim == 2 ? "drag: pan, right drag: push, wheel: zoom" : "drag: orbit, wheel: zoom");
  if (snap.dim == 2) push_settings(s, f);
  if (snap.dim == 3) cut_controls(snap, v);
}

/// Projector mode: the whole UI's scale (ui_look.h, applied by the main loop between frames) and theme.
void ui_look_controls(GuiState& s) {
  float scale = s.look.scale;
  if (ImGui::SliderFloat("UI scale", &scale, kUiScaleMin, kUiScaleMax, "%.2f x")) s.look.scale = step_ui_scale(scale, 0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Projector mode: every panel's text and widgets at this scale (Ctrl+= / Ctrl+-, Ctrl+0: 1x);\n"
                      "the font is rasterised at the new size. %s", s.look_text.c_str());
  ImGui::SameLine();
  ImGui::Checkbox("high contrast", &s.look.high_contrast);
}

}  // namespace

void panel_display(GuiState& s) {
  const StepperFrame* f = s.frame();
  render::ViewSettings& v = s.view;
  if (f == nullptr) return;
  const Snapshot& snap = f->snapshot;
  const SnapshotField* shown = snap.find(v.color_by);
  const bool profile = render::draws_profile(snap.dim, v.profile_axis);
  colour_controls(v, snap, shown, profile);
  if (std::any_of(snap.outlines.begin(), snap.outlines.end(),
                  [](const Outline& o) { return o.label == TrailLog::kLabel; })) {
    ImGui::Checkbox("orbit trails", &v.show_trails);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Each body's path so far (restarts on reset)");
  }
  if (f->config.params.physics.gravity == GravityType::Tree && snap.dim >= 2 && !profile && snap.count > 0)
    tree_cells_toggle(s, snap);
  ImGui::Checkbox("log10 scale", &v.log_scale);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Colour (and the profile's y axis) by log10 of the field: for densities spanning decades\n"
                      "(a collapse). Values <= 0 are not drawn. A fixed range is then in log10 units.");
  ImGui::SameLine();
  ImGui::Checkbox("auto", &v.auto_log);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Plane and 3D views: colour by log10 when the field spans more than two decades\n"
                      "between its 1st and 99th percentiles (a collapsed sphere's density), so that most\n"
                      "particles are not one colour");
  if (!v.auto_range) {
    float r[2] = {v.range_min, v.range_max};
    if (ImGui::InputFloat2("range", r, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue) && r[1] > r[0]) {
      v.range_min = r[0];
      v.range_max = r[1];
    }
  }
  if (snap.dim >= 2) panel_view_kind(v, snap.dim);
  if (profile) profile_controls(v, snap);
  else particle_controls(s, *f, v);
  ImGui::SliderInt("text size", &v.text_scale, 0, 4, v.text_scale == 0 ? "auto" : "%d x");
  ui_look_controls(s);
}

}  // namespace sph::gui
