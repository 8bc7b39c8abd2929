// Cameras: the visible world rectangle of the 2D view, the orbit camera of the 3D view, and the
// box both fit by default.
#pragma once
#include <array>

#include "mat4.h"
#include "view_settings.h"

namespace sph {
struct Snapshot;
}

namespace sph::render {

using Bounds = std::array<float, 6>;  ///< xmin, xmax, ymin, ymax, zmin, zmax [world units]

/// snapshot.bounds where it has positive extent along the snapshot's axes, else the particles'
/// extent; a zero extent is widened to 1 so that every view has a finite scale.
Bounds view_bounds(const sph::Snapshot& snap);

/// World rectangle [x0,x1]x[y0,y1] shown in a plot of pw x ph pixels (equal aspect).
struct WorldRect {
  float x0 = 0.f, x1 = 1.f, y0 = 0.f, y1 = 1.f;
};
WorldRect visible_rect_2d(const Bounds& bounds, const Camera2D& cam, float pw, float ph);

struct CameraMatrices {
  Mat4 view;  ///< world -> eye
  Mat4 proj;  ///< eye -> clip
  Vec3f eye;  ///< camera position [world units] (3D)
};

/// Orthographic camera showing exactly `rect` (z ignored).
CameraMatrices camera_2d(const WorldRect& rect);
/// Perspective orbit camera around the centre of `bounds`; aspect = plot width / height.
CameraMatrices camera_3d(const Bounds& bounds, const OrbitCamera& cam, float aspect);

}  // namespace sph::render
