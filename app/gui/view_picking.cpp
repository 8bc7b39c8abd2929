#include "view_picking.h"

#include <imgui.h>

#include "sph/snapshot.h"

namespace sph::gui {

void pick_particles(GuiState& s, const ParticleView& view, const Rect& r) {
  const StepperFrame* f = s.frame();
  const ImGuiIO& io = ImGui::GetIO();
  if (f == nullptr || io.WantCaptureMouse) return;
  const std::optional<render::Picked> p = view.particle_under_mouse(r);
  if (!p) return;
  const Snapshot& snap = p->run == 1 && f->comparing ? f->compare.snapshot : f->snapshot;
  if (p->index >= snap.count) return;
  const SnapshotField* field = snap.find(s.view.color_by);
  const char* run = f->comparing ? (p->run == 1 ? " (run B)" : " (run A)") : "";
  if (field && p->index < field->values.size())
    ImGui::SetTooltip("particle %u%s%s\n%s = %.6g\nclick: inspect", p->index, run, snap.is_wall(p->index) ? " (wall)" : "",
                      field->label.c_str(), field->values[p->index]);
  else
    ImGui::SetTooltip("particle %u%s\nclick: inspect", p->index, run);
  // a click, not the end of a drag (pan, orbit)
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.f)
    s.inspect(static_cast<std::int64_t>(p->index));
}

}  // namespace sph::gui
