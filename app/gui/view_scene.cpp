#include "view_scene.h"

#include <algorithm>
#include <cmath>

#include "sph/compare.h"

namespace sph::gui {
namespace {

std::vector<std::pair<std::string, double>> errors_of(const std::vector<RefColumn>& columns,
                                                      const std::vector<double>& values) {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t k = 0; k < columns.size() && k < values.size(); ++k) out.emplace_back(columns[k].name, values[k]);
  return out;
}

}  // namespace

render::Highlight highlight_of(const Inspection& in) {
  render::Highlight h;
  h.index = in.id;
  h.support = std::isfinite(in.support) ? static_cast<float>(in.support) : 0.f;
  double wmax = 0.0;
  for (const InspectNeighbour& n : in.neighbour_list) wmax = std::max(wmax, n.W);
  for (const InspectNeighbour& n : in.neighbour_list)
    if (n.id >= 0) h.neighbours.emplace_back(static_cast<std::uint32_t>(n.id), wmax > 0.0 ? static_cast<float>(n.W / wmax) : 0.f);
  return h;
}

render::FrameScene view_scene(const StepperFrame& f) {
  render::FrameScene scene;
  scene.a = &f.snapshot;
  if (f.comparing) {
    scene.b = &f.compare.snapshot;
    const std::string a = compare_label(f.config, f.compare.overrides);
    const std::string b = compare_label(f.compare.config, f.compare.overrides);
    scene.label_a = a.empty() ? "A" : "A: " + a;
    scene.label_b = b.empty() ? "B" : "B: " + b;
    scene.errors_a = errors_of(f.ref_columns, f.ref_values);
    scene.errors_b = errors_of(f.ref_columns, f.compare.ref_values);
  }
  if (!f.sweep.empty()) {  // run A labelled with its own value of the key, each sweep run with its value
    scene.sweep_key = f.sweep_key;
    render::name_sweep_run_a(scene, compare_label(f.config, f.sweep.front().overrides));
    scene.errors_a = errors_of(f.ref_columns, f.ref_values);
    for (const CompareFrame& r : f.sweep)
      render::add_sweep_run(scene, &r.snapshot, compare_label(r.config, r.overrides), errors_of(f.ref_columns, r.ref_values));
  }
  if (f.inspection) scene.highlight = highlight_of(*f.inspection);
  return scene;
}

}  // namespace sph::gui
