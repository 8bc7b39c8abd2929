// What one frame shows: a snapshot, or the two runs of an A/B comparison, or run A with the other runs of
// a parameter sweep, with their legend labels and reference errors, and optionally a particle picked out
// with its neighbours (the inspector).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "overlay_types.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

/// Colours of the runs of a comparison or a sweep (dots, captions and legend rows), and of the exact curve
/// drawn with them: bright against the dark plot fill and apart from each other for colour-blind viewers
/// (orange, sky blue, bluish green, yellow, vermillion, reddish purple: Okabe & Ito 2008).
inline constexpr int kRunColorCount = 6;
inline constexpr Rgba kRunColors[kRunColorCount] = {{0.90f, 0.62f, 0.00f, 1.f}, {0.34f, 0.71f, 0.91f, 1.f},
                                                    {0.00f, 0.62f, 0.45f, 1.f}, {0.94f, 0.89f, 0.26f, 1.f},
                                                    {0.84f, 0.37f, 0.00f, 1.f}, {0.80f, 0.47f, 0.65f, 1.f}};
inline constexpr Rgba kCompareExact{0.96f, 0.96f, 0.96f, 1.f};

/// A particle drawn with a ring (the inspected one), its neighbours with fainter rings whose strength
/// is their kernel weight.
struct Highlight {
  int run = 0;              ///< 0: in the first snapshot, 1: in run B
  std::int64_t index = -1;  ///< snapshot index of the picked particle; < 0: nothing highlighted
  std::vector<std::pair<std::uint32_t, float>> neighbours;  ///< snapshot index, weight in [0, 1]
  float support = 0.f;      ///< the picked particle's kernel support radius [length]; 0: not drawn
  bool operator==(const Highlight&) const = default;
};

/// One more run of a parameter sweep, drawn over run A in the profiles.
struct SweepRun {
  const sph::Snapshot* snap = nullptr;
  std::string label;        ///< its legend name ("kernel.eta=1.5")
  std::string value;        ///< the swept value alone ("1.5"), for the legends of small panels
  std::vector<std::pair<std::string, double>> errors;  ///< its reference values, as errors_a
};

/// A run's index in Picked::run and ParticleBatch::run: 0 run A, 1 run B, 2 + k the sweep's run k.
inline constexpr int kFirstSweepRun = 2;

struct FrameScene {
  const sph::Snapshot* a = nullptr;  ///< the run shown (run A of a comparison)
  const sph::Snapshot* b = nullptr;  ///< run B of a comparison, or nullptr
  std::string label_a = "A", label_b = "B";  ///< the runs' legend names
  /// Their reference values (column name, value): a profile's legend shows "L1_<field>" of each run.
  std::vector<std::pair<std::string, double>> errors_a, errors_b;
  /// A parameter sweep's other runs (none: no sweep); profiles draw them over run A in kRunColors[1..],
  /// particle views show run A alone. Its key is sweep_key; value_a is run A's value marked ("1.2 (A)").
  std::vector<SweepRun> sweep;
  std::string sweep_key, value_a;
  Highlight highlight;
};

/// `text` marked as run A's: "1.2 (A)", and "1.2 (default, A)" for a text that ends in a parenthesis.
inline std::string mark_run_a(const std::string& text) {
  if (!text.empty() && text.back() == ')') return text.substr(0, text.size() - 1) + ", A)";
  return text + " (A)";
}

/// The value of a "key=value" label ("1.5" of "kernel.eta=1.5").
inline std::string value_of_label(const std::string& label) { return label.substr(label.find('=') + 1); }

/// Names run A of a sweep by its "key=value" label (compare_label's): label_a and value_a, both marked.
inline void name_sweep_run_a(FrameScene& scene, const std::string& label) {
  scene.label_a = mark_run_a(label);
  scene.value_a = mark_run_a(value_of_label(label));
}

/// Adds a sweep's run, named by its "key=value" label, with its reference values.
inline void add_sweep_run(FrameScene& scene, const sph::Snapshot* snap, const std::string& label,
                          std::vector<std::pair<std::string, double>> errors) {
  scene.sweep.push_back({snap, label, value_of_label(label), std::move(errors)});
}

/// What a pixel shows (Renderer::pick): a particle of run 0 (A), 1 (B) or kFirstSweepRun + k (a sweep's
/// run k), by snapshot index.
struct Picked {
  int run = 0;
  std::uint32_t index = 0;
  float distance_px = 0.f;  ///< from the point asked about to the particle's centre
};

/// The reference column of a field: "L1_rho" for rho, "L1_v" for vx (the tubes' columns), "" if none.
std::string error_column(const std::vector<std::pair<std::string, double>>& errors, const std::string& field,
                         double* value);

}  // namespace sph::render
