// One line along the bottom: where the run is (t, dt, step), how fast the engine goes (steps/s,
// particle-steps/s), what the density solve did (mean neighbours, h-iterations), the display rate,
// and the last notice.
#include <imgui.h>

#include <cstdio>

#include "frame_stats.h"
#include "panels.h"

namespace sph::gui {

void status_line(GuiState& s, const FrameStats& stats) {
  const StepperFrame* f = s.frame();
  if (f == nullptr) {
    ImGui::TextUnformatted("building the scene ...");
    return;
  }
  const char* state = f->diverged ? "DIVERGED" : f->running ? "running" : f->at_end ? "at t_end" : "paused";
  const ImVec4 colour = f->diverged ? ImVec4(1.f, 0.35f, 0.35f, 1.f)
                        : f->running ? ImVec4(0.5f, 0.9f, 0.5f, 1.f)
                                     : ImVec4(1.f, 0.8f, 0.35f, 1.f);
  ImGui::TextColored(colour, "%-8s", state);
  ImGui::SameLine();
  if (const StepperFrame* shown = s.shown_frame(); shown != f) {  // scrubbing: which stored frame the view shows
    ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.f, 1.f), "viewing t = %.5g (%d/%zu, view only)  |", shown->snapshot.t,
                       s.scrub + 1, s.ring.size());
    ImGui::SameLine();
  }
  if (!s.pace_note.empty()) {  // first: a projector's status line is cut at the right
    ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.f, 1.f), "%s  |", s.pace_note.c_str());
    ImGui::SameLine();
  }
  const Snapshot& snap = f->snapshot;
  ImGui::Text("t = %.5g   dt = %.3g   step %lld   |   %.4g steps/s   %.3g particle-steps/s   |   N = %zu   "
              "<neighbours> %.1f   h-iterations %.2f (max %d)   |   display %.0f fps (%.0f drawn)",
              snap.t, snap.dt, static_cast<long long>(snap.step), f->steps_per_second, f->particle_steps_per_second,
              snap.count, f->density.mean_neighbours, f->density.mean_iterations, f->density.max_iterations,
              stats.fps(), stats.drawn_fps());
  if (f->record_every > 0.0) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.f, 0.35f, 0.35f, 1.f), "   REC every %g", f->record_every);
  }
  if (!f->warnings.empty()) {  // what the run tolerated: the newest first kind in full on hover
    ImGui::SameLine();
    const RunWarning& w = f->warnings.front();
    ImGui::TextColored(ImVec4(1.f, 0.7f, 0.2f, 1.f), "   %zu warning%s: [%s] %s", f->warnings.size(),
                       f->warnings.size() == 1 ? "" : "s", w.kind.c_str(), w.message.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (const RunWarning& x : f->warnings)
        ImGui::Text("[%s] from step %lld (t = %.4g): %s", x.kind.c_str(), static_cast<long long>(x.step), x.t,
                    x.message.c_str());
      ImGui::EndTooltip();
    }
  }
  if (!s.message.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(s.message_is_error ? ImVec4(1.f, 0.45f, 0.45f, 1.f) : ImVec4(0.6f, 0.6f, 0.65f, 1.f), "   %s",
                       s.message.c_str());
  }
}

}  // namespace sph::gui
