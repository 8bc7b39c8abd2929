// A region of a 2D scene worth a closer look than the whole domain allows (the inner planets of the Solar
// System, 1.5 AU inside an orbit of Pluto at 40 AU): a 2D view draws it enlarged in a corner of the plot.
// A hint about the scene, not a view setting: the engine only passes it on (SceneSpec -> Snapshot).
#pragma once
#include <string>

namespace sph {

struct ViewInset {
  double cx = 0.0, cy = 0.0;  ///< centre [length]
  double half = 0.0;          ///< half its side [length]; 0: no inset
  std::string label;          ///< its caption ("inner planets")
};

}  // namespace sph
