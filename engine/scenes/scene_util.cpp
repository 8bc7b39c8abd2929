#include "scene_util.h"

#include "core/pipeline.h"
#include "sph/kernel.h"

namespace sph::scenes {

Particles make_particles(const Params& prm, int dim, std::size_t n) {
  return Particles(dim, n, Pipeline(prm.physics, dim).fields());
}

double effective_eta(const Params& prm, int dim) {
  return prm.kernel.eta > 0.0 ? prm.kernel.eta : Kernel(prm.kernel.type, dim).default_eta();
}

}  // namespace sph::scenes
