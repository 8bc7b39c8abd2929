// What one frame shows: a snapshot, or the two runs of an A/B comparison with their legend labels and
// reference errors, and optionally a particle picked out with its neighbours (the inspector).
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

/// Colours of the runs of a comparison (dots, captions and legend rows), and of the exact curve drawn
/// with them: bright against the dark plot fill and apart from each other for colour-blind viewers
/// (orange and sky blue, Okabe & Ito 2008).
inline constexpr Rgba kRunColors[2] = {{0.90f, 0.62f, 0.00f, 1.f}, {0.34f, 0.71f, 0.91f, 1.f}};
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

struct FrameScene {
  const sph::Snapshot* a = nullptr;  ///< the run shown (run A of a comparison)
  const sph::Snapshot* b = nullptr;  ///< run B of a comparison, or nullptr
  std::string label_a = "A", label_b = "B";  ///< the runs' legend names
  /// Their reference values (column name, value): a profile's legend shows "L1_<field>" of each run.
  std::vector<std::pair<std::string, double>> errors_a, errors_b;
  Highlight highlight;
};

/// What a pixel shows (Renderer::pick): a particle of run 0 (A) or 1 (B), by snapshot index.
struct Picked {
  int run = 0;
  std::uint32_t index = 0;
  float distance_px = 0.f;  ///< from the point asked about to the particle's centre
};

/// The reference column of a field: "L1_rho" for rho, "L1_v" for vx (the tubes' columns), "" if none.
std::string error_column(const std::vector<std::pair<std::string, double>>& errors, const std::string& field,
                         double* value);

}  // namespace sph::render
