#include "view_picking.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "frame_scene.h"
#include "sph/snapshot.h"

namespace sph::gui {

void pick_particles(GuiState& s, const ParticleView& view, const Rect& r) {
  const StepperFrame* f = s.frame();
  const ImGuiIO& io = ImGui::GetIO();
  if (f == nullptr || io.WantCaptureMouse) return;
  const std::optional<render::Picked> p = view.particle_under_mouse(r);
  if (!p) return;
  // a sweep run's particle: its values in the tooltip; the inspector follows run A (and run B) only
  const std::size_t sweep = static_cast<std::size_t>(std::max(0, p->run - render::kFirstSweepRun));
  const bool swept = p->run >= render::kFirstSweepRun && sweep < f->sweep.size();
  const Snapshot& snap = swept ? f->sweep[sweep].snapshot : p->run == 1 && f->comparing ? f->compare.snapshot : f->snapshot;
  if (p->index >= snap.count) return;
  const SnapshotField* field = snap.find(s.view.color_by);
  const std::string sweep_run = swept && !f->sweep[sweep].overrides.empty() ? " (" + f->sweep[sweep].overrides.front() + ")" : "";
  const char* run = swept ? sweep_run.c_str() : f->comparing ? (p->run == 1 ? " (run B)" : " (run A)") : "";
  if (field && p->index < field->values.size())
    ImGui::SetTooltip("particle %u%s%s\n%s = %.6g%s", p->index, run, snap.is_wall(p->index) ? " (wall)" : "",
                      field->label.c_str(), field->values[p->index], swept ? "" : "\nclick: inspect");
  else
    ImGui::SetTooltip("particle %u%s%s", p->index, run, swept ? "" : "\nclick: inspect");
  // a click, not the end of a drag (pan, orbit)
  if (!swept && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.f)
    s.inspect(static_cast<std::int64_t>(p->index));
}

}  // namespace sph::gui
