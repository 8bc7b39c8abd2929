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

void without_sph(SceneSpec& s) {
  Physics& ph = s.defaults.physics;
  ph.density = DensityMode::None;
  ph.smoothing = HMode::Fixed;
  ph.eos = EosType::None;
  ph.force = ForceType::None;
  ph.viscosity = ViscType::None;
  ph.energy = Toggle::Off;
  for (Slot slot : {Slot::Density, Slot::Eos, Slot::Force, Slot::Viscosity, Slot::Xsph, Slot::Conduction, Slot::Energy,
                    Slot::BodyForce, Slot::Walls})
    s.allow(slot, {"none"});
  s.allow(Slot::Smoothing, {"fixed"});
}

}  // namespace sph::scenes
