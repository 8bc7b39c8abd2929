// A copy of what a viewer needs from the engine: the renderer reads this, never engine internals.
// Floats (the renderer's precision); the engine stays double precision.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sph/view_inset.h"

namespace sph {

/// One scalar field per particle, with its range over the fluid particles.
struct SnapshotField {
  std::string name;           ///< key used by --color-by and the GUI ("rho", "p", "u", "speed", "h", ...)
  std::string label;          ///< human label with unit, e.g. "density rho"
  std::vector<float> values;  ///< one value per particle
  float min = 0.f, max = 0.f; ///< range over the fluid particles (finite values only; walls excluded)
};

/// An exact or reference solution sampled on a line: value(x) for one field, x along coordinate `axis`
/// (1D profile plots).
struct ExactCurve {
  std::string field;        ///< same key as SnapshotField::name
  std::vector<float> x;     ///< abscissae, increasing
  std::vector<float> value; ///< reference value at x
  int axis = 0;             ///< which coordinate x is: 0..2, or 3 for the distance r from the origin
};

/// A reference shape in the plane (world coordinates), e.g. the exact ellipse of a drop or a measured
/// surge front: drawn over 2D views.
struct Outline {
  std::string label;     ///< legend text
  std::vector<float> x;  ///< vertices of a polyline
  std::vector<float> y;
};

/// A cell of the Barnes-Hut walk of one particle (the tree overlay): where it is and how it is used.
struct TreeCell {
  std::array<float, 3> center{};  ///< geometric centre [length]
  float half = 0.f;               ///< half its side [length]
  bool whole = false;             ///< used whole (multipole); false: a leaf summed particle by particle
};

struct Snapshot {
  std::string scene;           ///< scene name
  int dim = 2;                 ///< 1, 2 or 3
  std::int64_t step = 0;       ///< engine step number
  double t = 0.0;              ///< simulated time
  double dt = 0.0;             ///< last timestep
  std::size_t count = 0;       ///< number of (real) particles; every array below has this length
  std::vector<float> x, y, z;  ///< positions (y, z are 0 below their dimension)
  std::vector<float> h;        ///< smoothing length (disc radius in 2D views)
  std::vector<std::uint8_t> kind;  ///< sph::Kind per particle (0 fluid, 1 wall: drawn grey); empty = all fluid
  std::vector<SnapshotField> fields;  ///< the active display fields
  std::vector<ExactCurve> exact;      ///< reference curves (1D scenes with an exact solution)
  std::vector<Outline> outlines;      ///< reference shapes (2D scenes)
  std::array<float, 6> bounds{0, 1, 0, 1, 0, 1};  ///< domain box xmin,xmax,ymin,ymax,zmin,zmax
  /// The tree's cells as the walk of particle tree_probe (an index into the arrays above) uses them at
  /// the current theta; empty unless a viewer asked for them and the scene's gravity is the tree.
  std::vector<TreeCell> tree_cells;
  std::int64_t tree_probe = -1;
  /// A plot that is not a simulation state (a convergence study): its own title line instead of
  /// "scene t = .. step ..", and the profile's x-axis label instead of the coordinate's name.
  std::string title, x_label;
  std::string y_label;  ///< a 2D plot's vertical axis label instead of "y" (the work-precision plot)
  std::string points_label, curve_label;  ///< the 1D legend's rows (empty: "SPH particles", "exact")
  ViewInset inset;  ///< the scene's region for an enlarged inset of the plane view (SceneSpec::inset)

  /// The field with this name, or nullptr.
  const SnapshotField* find(std::string_view name) const {
    for (const auto& f : fields)
      if (f.name == name) return &f;
    return nullptr;
  }
  bool is_wall(std::size_t i) const { return i < kind.size() && kind[i] != 0; }
  const ExactCurve* find_exact(std::string_view name) const {
    for (const auto& c : exact)
      if (c.field == name) return &c;
    return nullptr;
  }
};

}  // namespace sph
