// Control-point tables of the built-in colour maps (data only; see colormap_tables.cpp for sources).
#pragma once
#include <span>
#include <string_view>

#include "colormap.h"

namespace sph::render {

/// One control point: position (in the table's own units, see ColormapTable::position_scale) and sRGB.
struct ControlPoint {
  float position;  ///< t * position_scale, t in [0,1]
  float r, g, b;   ///< sRGB in [0,1]
};

struct ColormapTable {
  std::string_view name;
  float position_scale;                ///< divide ControlPoint::position by this to get t in [0,1]
  std::span<const ControlPoint> points;  ///< increasing position, first at 0, last at position_scale
  Rgb contrast;                        ///< a colour absent from the map, for curves drawn over it
};

const ColormapTable& colormap_table(Colormap map);

}  // namespace sph::render
