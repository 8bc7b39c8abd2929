#include "nbody_common.h"

#include "scene_util.h"

namespace sph::scenes {

void make_nbody(SceneSpec& s, GravityType type, double G) {
  without_sph(s);
  s.defaults.physics.gravity = type;
  s.defaults.gravity.G = G;
  s.defaults.time.integrator = IntegratorType::Leapfrog;
  s.allow(Slot::Gravity, {"direct", "tree", "fmm"});
}

SceneSetup bodies_setup(const Params& prm, int dim, const std::vector<Body>& bodies, double half_box) {
  Particles p = make_particles(prm, dim, bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    p[Field::Mass][i] = b.m;
    p[Field::H][i] = 0.0;
    const double x[3] = {b.x.x, b.x.y, b.x.z}, v[3] = {b.v.x, b.v.y, b.v.z};
    for (int k = 0; k < dim; ++k) { p.x[k][i] = x[k]; p.v[k][i] = v[k]; }
  }
  SceneSetup out{std::move(p), {}, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    out.domain.lo[k] = k < dim ? -half_box : 0.0;
    out.domain.hi[k] = k < dim ? half_box : 1.0;
  }
  return out;
}

}  // namespace sph::scenes
