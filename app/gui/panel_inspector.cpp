// The particle inspector: the particle picked in the view (or typed by id) taken apart by
// Report::inspect on the engine thread - its fields, the terms of its momentum and energy equations
// for the scene's formulation with their sums against the rates the engine computes, what heats it,
// and its neighbours with their kernel weights (ringed in the view).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "panels.h"

namespace sph::gui {
namespace {

void field_row(const char* name, double v, const char* tip) {
  if (std::isnan(v)) return;
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  ImGui::TableNextColumn();
  ImGui::Text("%.6g", v);
}

void fields(const Inspection& in) {
  if (!ImGui::BeginTable("fields", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) return;
  field_row("x", in.x.x, "position x [length]");
  if (in.x.y != 0.0 || in.x.z != 0.0) field_row("y", in.x.y, "position y [length]");
  if (in.x.z != 0.0) field_row("z", in.x.z, "position z [length]");
  field_row("|v|", in.speed, "speed [length/time]");
  field_row("rho", in.rho, "density [mass/length^d]");
  field_row("P", in.P, "pressure");
  field_row("u", in.u, "specific internal energy [length^2/time^2]");
  field_row("h", in.h, "smoothing length [length]");
  field_row("Omega", in.omega, "grad-h term (seed 000 eq. 3.3.2) [dimensionless]");
  field_row("c", in.c, "sound speed [length/time]");
  field_row("neighbours", in.neighbours, "inside its own support (itself included)");
  field_row("h-iterations", in.h_iterations, "Newton-Raphson iterations of its last h solve (seed 000 eq. 3.5.1)");
  field_row("drho/dt", in.drhodt, "continuity rate (seed 001 eq. 39)");
  ImGui::EndTable();
}

/// One row of the terms table: the name (its equation on hover), a's components, du/dt.
void term_row(const char* name, const char* tip, const Vec3& a, double dudt, int dim, bool energy, bool strong) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  if (strong) ImGui::TextColored(ImVec4(1.f, 0.85f, 0.4f, 1.f), "%s", name);
  else ImGui::TextUnformatted(name);
  if (tip && *tip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  const double c[3] = {a.x, a.y, a.z};
  for (int k = 0; k < dim; ++k) {
    ImGui::TableNextColumn();
    ImGui::Text("%+.4g", c[k]);
  }
  if (energy) {
    ImGui::TableNextColumn();
    ImGui::Text("%+.4g", dudt);
  }
}

void terms(const Inspection& in, int dim, const char* id) {
  if (in.wall) {
    ImGui::TextDisabled("a wall particle: fixed, no equations of motion");
    return;
  }
  ImGui::Text("%s formulation", in.formulation.empty() ? "no force stage:" : in.formulation.c_str());
  const int cols = 1 + dim + (in.has_energy ? 1 : 0);
  if (!ImGui::BeginTable(id, cols, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV))
    return;
  const char* axes[3] = {"a_x", "a_y", "a_z"};
  ImGui::TableSetupColumn("term");
  for (int k = 0; k < dim; ++k) ImGui::TableSetupColumn(axes[k]);
  if (in.has_energy) ImGui::TableSetupColumn("du/dt");
  ImGui::TableHeadersRow();
  Vec3 sum;
  double du = 0.0;
  for (const InspectTerm& t : in.terms) {
    term_row(t.name.c_str(), t.source.c_str(), t.a, t.dudt, dim, in.has_energy, false);
    sum += t.a;
    du += t.dudt;
  }
  term_row("sum of the terms", "", sum, du, dim, in.has_energy, true);
  term_row("engine's rates", "the stages' own result for this particle, re-evaluated at this state", in.a_total,
           in.dudt_total, dim, in.has_energy, false);
  term_row("run's last rates", "from the run's last evaluation (leapfrog evaluates at the predicted velocity)",
           in.a_stored, in.dudt_stored, dim, in.has_energy, false);
  ImGui::EndTable();
  if (!in.has_energy) return;
  // "why did this particle heat up?": the largest heating term and its share of all heating
  double heat = 0.0;
  const InspectTerm* top = nullptr;
  for (const InspectTerm& t : in.terms) {
    if (t.dudt > 0.0) heat += t.dudt;
    if (t.dudt > 0.0 && (!top || t.dudt > top->dudt)) top = &t;
  }
  if (top) ImGui::TextWrapped("u %s; heating mostly by %s (%.0f%% of the positive terms)",
                              in.dudt_total > 0.0 ? "rises" : "falls", top->name.c_str(), 100.0 * top->dudt / heat);
}

void neighbours(const Inspection& in, bool energy) {
  char title[64];
  std::snprintf(title, sizeof title, "%zu neighbours (ringed in the view)", in.neighbour_list.size());
  if (!ImGui::TreeNode(title)) return;
  std::vector<std::size_t> order(in.neighbour_list.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return in.neighbour_list[a].W > in.neighbour_list[b].W; });
  if (ImGui::BeginTable("nb", energy ? 5 : 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("id");
    ImGui::TableSetupColumn("r/h");
    ImGui::TableSetupColumn("W share");
    ImGui::TableSetupColumn("|a| pair");
    if (energy) ImGui::TableSetupColumn("du/dt pair");
    ImGui::TableHeadersRow();
    for (std::size_t k : order) {
      const InspectNeighbour& n = in.neighbour_list[k];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%lld%s", static_cast<long long>(n.id), n.ghost ? " (image)" : n.wall ? " (wall)" : "");
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", n.r / in.h);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", n.share);
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", n.a.norm());
      if (energy) {
        ImGui::TableNextColumn();
        ImGui::Text("%+.4g", n.dudt);
      }
    }
    ImGui::EndTable();
  }
  ImGui::TreePop();
}

}  // namespace

void panel_inspector(GuiState& s) {
  const StepperFrame* f = s.frame();
  int id = static_cast<int>(s.inspect_id);
  ImGui::SetNextItemWidth(8.f * ImGui::GetFontSize());
  if (ImGui::InputInt("particle id", &id, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) && f && id >= 0 &&
      static_cast<std::size_t>(id) < f->snapshot.count)
    s.inspect(id);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type an id (or click a particle in the view); ids are stable");
  ImGui::SameLine();
  if (ImGui::SmallButton("close")) s.inspect(-1);
  if (f == nullptr || !f->inspection) {
    ImGui::TextDisabled("waiting for the engine ...");
    return;
  }
  const Inspection& in = *f->inspection;
  const int dim = std::clamp(f->snapshot.dim, 1, 3);
  ImGui::Text("particle %lld%s at step %lld, t = %.5g", static_cast<long long>(in.id), f->comparing ? " in run A" : "",
              static_cast<long long>(in.step), in.t);
  fields(in);
  terms(in, dim, "termsA");
  neighbours(in, in.has_energy);
  if (f->comparing && f->compare.inspection && ImGui::CollapsingHeader("the same particle in run B")) {
    fields(*f->compare.inspection);
    terms(*f->compare.inspection, dim, "termsB");
  }
}

}  // namespace sph::gui
