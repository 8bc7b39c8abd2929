#include "scene_util.h"

#include "sph/kernel.h"

namespace sph::scenes {

Particles make_particles(const SceneSpec& spec, std::size_t n) { return Particles(spec.dim, n, fields_for(spec.modules)); }

double effective_eta(const Params& prm, int dim) {
  return prm.eta > 0.0 ? prm.eta : Kernel(prm.kernel, dim).default_eta();
}

}  // namespace sph::scenes
