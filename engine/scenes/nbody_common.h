// What the gravity scenes share: the physics of a pure N-body run (no density, no EOS, no hydro:
// only the self-gravity stage) and point masses placed as given.
#pragma once
#include <vector>

#include "sph/scene.h"

namespace sph::scenes {

/// A point mass [mass], its position [length] and velocity [length/time].
struct Body {
  double m;
  Vec3 x, v;
};

/// Pure N-body: every hydro slot none, gravity `type`, G, leapfrog; restricts the scene's slots to that.
void make_nbody(SceneSpec& s, GravityType type, double G);

/// The particles of `bodies` (h = 0: point masses).
SceneSetup bodies_setup(const Params& prm, int dim, const std::vector<Body>& bodies, double half_box);

}  // namespace sph::scenes
