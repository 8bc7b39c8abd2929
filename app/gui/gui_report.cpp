// sph-gui's exit report: one line per item, numbers in full precision where a test recomputes them.
#include "gui_report.h"

#include <imgui.h>

#include <cstdio>
#include <string>

#include "layout_check.h"
#include "text_layout.h"
#include "lesson_job.h"

namespace sph::gui {
namespace {

/// What the view showed last, for scripted checks: its legend rows and the inspected particle's numbers
/// (17 digits: a test recomputes them with Report::inspect).
void report_view(const ParticleView& view, const StepperFrame& f) {
  std::string rows;
  for (const std::string& r : view.layout().legend_rows) rows += (rows.empty() ? "" : " | ") + r;
  if (view.drawn_step() >= 0)
    std::printf("sph-gui: view drawn from step %lld, t = %.9g\n", view.drawn_step(), view.drawn_time());
  if (!rows.empty()) std::printf("sph-gui: view legend: %s\n", rows.c_str());
  if (!f.inspection) return;
  const Inspection& in = *f.inspection;
  std::printf("sph-gui: inspected particle %lld at step %lld, t = %.17g: x = %.17g, rho = %.17g, u = %.17g, "
              "a_x = %.17g, du/dt = %.17g\n",
              static_cast<long long>(in.id), static_cast<long long>(in.step), in.t, in.x.x, in.rho, in.u, in.a_total.x,
              in.dudt_total);
  for (const InspectTerm& t : in.terms)
    std::printf("sph-gui: term %s: a_x = %.17g, du/dt = %.17g\n", t.name.c_str(), t.a.x, t.dudt);
}

/// The lesson step's check at exit (waits for it): for scripted checks of the panel.
void report_lesson(GuiState& s) {
  LessonUi& L = s.lesson;
  if (!L.lesson) return;
  const LessonStep& st = L.lesson->steps[static_cast<std::size_t>(L.step)];
  if (!st.predict.empty())
    std::printf("sph-gui: lesson step %d predicts: %s\nsph-gui: answer %s\n", L.step + 1, st.predict.c_str(),
                L.answer_shown ? ("shown: " + st.answer).c_str() : "hidden");
  if (!L.job) return;
  L.job->wait();
  const int n = static_cast<int>(L.lesson->steps.size());
  if (!L.job->error().empty())
    std::printf("sph-gui: lesson step %d/%d: error: %s\n", L.job_step + 1, n, L.job->error().c_str());
  else if (L.job->result())
    std::printf("sph-gui: lesson step %d/%d: %s: %s\n", L.job_step + 1, n, L.job->result()->pass ? "true" : "FALSE",
                L.job->result()->text.c_str());
}

}  // namespace

void report_exit(GuiState& state, const ParticleView& view, const Recorder& recorder, const FrameStats& stats,
                 const EngineRate& engine_rate, const UiLook& applied, int threads) {
  const StepperFrame* f = state.frame();
  std::printf("sph-gui: %lld frames in %.2f s: %.1f display fps (%.1f drawn/s); engine %.4g steps/s (%.3g "
              "particle-steps/s, %zu particles, %d threads)\n",
              static_cast<long long>(stats.frames()), stats.seconds(), stats.mean_fps(), stats.mean_drawn_fps(),
              engine_rate.rate(),
              engine_rate.rate() * static_cast<double>(f ? f->snapshot.count : 0), f ? f->snapshot.count : 0,
              threads);
  if (recorder.frames() > 0) std::printf("sph-gui: %d frames in %s/\n", recorder.frames(), recorder.dir().c_str());
  if (f) std::printf("sph-gui: last state: step %lld, t = %.9g\n", static_cast<long long>(f->snapshot.step), f->snapshot.t);
  if (f) report_view(view, *f);
  if (f && !f->pushes.empty())
    std::printf("sph-gui: pushes: %zu changes logged, %s; momentum P = (%.6g, %.6g)\n", f->pushes.size(),
                f->push.active() ? "one acting" : "none acting", f->diagnostics.P[0], f->diagnostics.P[1]);
  if (const StepperFrame* shown = state.shown_frame(); shown && shown != f)
    std::printf("sph-gui: view shows stored frame %d of %zu: step %lld, t = %.9g\n", state.scrub + 1, state.ring.size(),
                static_cast<long long>(shown->snapshot.step), shown->snapshot.t);
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  std::printf("sph-gui: ui: scale %.2f%s, %s, font %.0f px, atlas %d x %d\n", applied.scale,
              applied.high_contrast ? ", high contrast" : "", state.look_text.empty() ? "start font" : state.look_text.c_str(),
              ImGui::GetFontSize(), atlas.TexWidth, atlas.TexHeight);
  if (!state.pace_note.empty()) std::printf("sph-gui: pace: %s\n", state.pace_note.c_str());
  report_lesson(state);
}

void report_layout(const ParticleView& view, const GuiState& state) {
  const ImDrawData* dd = ImGui::GetDrawData();
  if (dd == nullptr) return;
  const LayoutReport r = check_layout(*dd, *ImGui::GetIO().Fonts);
  std::printf("sph-gui: layout: %s\n", layout_text(r).c_str());
  const render::FrameLayout& frame = view.layout();
  const render::TextLayoutReport v =
      render::check_text(view.texts(), static_cast<float>(frame.width), static_cast<float>(frame.height));
  std::printf("sph-gui: view text: %s\n", render::text_layout_text(v).c_str());
  std::printf("sph-gui: Parameters header at y = %.0f while running, %.0f while stopped (-1: not seen)\n",
              double(state.params_row.running), double(state.params_row.stopped));
}

}  // namespace sph::gui
