// One line along the bottom: where the run is (t, dt, step), how fast the engine goes (steps/s,
// particle-steps/s), what the density solve did (mean neighbours, h-iterations), the display rate,
// and the last notice.
#include <imgui.h>

#include <cstdio>
#include <optional>
#include <string>

#include "frame_stats.h"
#include "panels.h"

namespace sph::gui {
namespace {

/// The room left on the line after the last item [px].
float room() {
  return ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x -
         ImGui::GetStyle().ItemSpacing.x;
}

/// A segment after the last item if it fits whole (or `first`: the line's first segment); false if left out.
bool segment(const char* text, std::optional<ImVec4> colour, bool first = false) {
  const float gap = ImGui::CalcTextSize("   ").x;
  if (!first && gap + ImGui::CalcTextSize(text).x > room()) return false;
  ImGui::SameLine(0.f, first ? -1.f : gap);
  if (colour) ImGui::TextColored(*colour, "%s", text);
  else ImGui::TextUnformatted(text);
  return true;
}

/// Text cut to the room left, ending in "..."; false if not even a few characters fit.
bool elided(const std::string& text, const ImVec4& colour) {
  const float gap = ImGui::CalcTextSize("   ").x, avail = room() - gap;
  std::string shown = text;
  if (ImGui::CalcTextSize(shown.c_str()).x > avail) {
    const float dots = ImGui::CalcTextSize("...").x;
    while (!shown.empty() && ImGui::CalcTextSize(shown.c_str()).x + dots > avail) shown.pop_back();
    if (shown.size() < 4) return false;
    shown += "...";
  }
  ImGui::SameLine(0.f, gap);
  ImGui::TextColored(colour, "%s", shown.c_str());
  return true;
}

}  // namespace

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
  // Segments while they fit the window; a segment that does not is left out (the window was cut at
  // 1.5x), the warning and the notice shortened to what is left, in full on hover.
  char buf[160];
  std::snprintf(buf, sizeof buf, "t = %.5g   dt = %.3g   step %lld", snap.t, snap.dt, static_cast<long long>(snap.step));
  segment(buf, std::nullopt, true);
  std::snprintf(buf, sizeof buf, "|   %.4g steps/s   %.3g particle-steps/s", f->steps_per_second,
                f->particle_steps_per_second);
  segment(buf, std::nullopt);
  if (f->config.params.physics.eos == EosType::Dfsph) {  // h is fixed: the pressure solves of the last step instead
    const Diagnostics& d = f->diagnostics;
    std::snprintf(buf, sizeof buf, "|   N = %zu   <neighbours> %.1f   DFSPH %d + %d iterations, density error %.2g%% (max %.2g%%)",
                  snap.count, f->density.mean_neighbours, d.dfsph_iter, d.dfsph_div_iter, 100.0 * d.dfsph_error,
                  100.0 * d.dfsph_error_max);
  } else {
    std::snprintf(buf, sizeof buf, "|   N = %zu   <neighbours> %.1f   h-iterations %.2f (max %d)", snap.count,
                  f->density.mean_neighbours, f->density.mean_iterations, f->density.max_iterations);
  }
  segment(buf, std::nullopt);
  std::snprintf(buf, sizeof buf, "|   display %.0f fps (%.0f drawn)", stats.fps(), stats.drawn_fps());
  segment(buf, std::nullopt);
  if (f->record_every > 0.0) {
    std::snprintf(buf, sizeof buf, "REC every %g", f->record_every);
    segment(buf, ImVec4(1.f, 0.35f, 0.35f, 1.f));
  }
  if (!f->warnings.empty()) {  // what the run tolerated: the newest first kind in full on hover
    const RunWarning& w = f->warnings.front();
    const std::string text = std::to_string(f->warnings.size()) + " warning" + (f->warnings.size() == 1 ? "" : "s") +
                             ": [" + w.kind + "] " + w.message;
    if (elided(text, ImVec4(1.f, 0.7f, 0.2f, 1.f)) && ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (const RunWarning& x : f->warnings)
        ImGui::Text("[%s] from step %lld (t = %.4g): %s", x.kind.c_str(), static_cast<long long>(x.step), x.t,
                    x.message.c_str());
      ImGui::EndTooltip();
    }
  }
  if (!s.message.empty() &&
      elided(s.message, s.message_is_error ? ImVec4(1.f, 0.45f, 0.45f, 1.f) : ImVec4(0.6f, 0.6f, 0.65f, 1.f)) &&
      ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", s.message.c_str());
}

}  // namespace sph::gui
