#include "scene_util.h"

#include <utility>

#include "core/pipeline.h"
#include "sph/kernel.h"

namespace sph::scenes {

Particles make_particles(const Params& prm, int dim, std::size_t n) {
  return Particles(dim, n, Pipeline(prm, dim).fields());
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

SceneSpec scene_head(std::string name, std::string category, std::string description, int dim, UnitSystem units) {
  SceneSpec s;
  s.name = std::move(name);
  s.category = std::move(category);
  s.description = std::move(description);
  s.dim = dim;
  s.units = std::move(units);
  return s;
}

SceneSpec gas_test_scene(std::string name, std::string category, std::string description, int dim, KernelType kernel,
                         double gamma, double alpha, double beta) {
  SceneSpec s = scene_head(std::move(name), std::move(category), std::move(description), dim);
  s.defaults.kernel.type = kernel;
  s.defaults.gas.gamma = gamma;
  s.defaults.visc.alpha = alpha;
  s.defaults.visc.beta = beta;
  s.allow(Slot::Eos, {"ideal_gas"});  // the references are ideal-gas solutions
  s.allow(Slot::Walls, {"none"});
  return s;
}

}  // namespace sph::scenes
